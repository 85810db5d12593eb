// Conversions between port text, blackboard values and JSON, with the Java executor's rules.
#pragma once

#include <behaviortree_cpp/utils/safe_any.hpp>
#include <behaviortree_cpp/blackboard.h>
#include <behaviortree_cpp/contrib/json.hpp>  // the nlohmann::json BehaviorTree.CPP ships (one copy: no ODR clash)

#include <string>

namespace miron::btcpp
{

/** A literal as a JSON scalar: an int, else a plain decimal number, else the text (Conversions.toScalar). */
nlohmann::json toScalar(const std::string& literal);

/** A blackboard value as JSON: text through toScalar (SubTree literals are text), numbers, booleans. */
nlohmann::json toJson(const BT::Any& value);

/** Writes a JSON value (a skill's output) to a blackboard key. */
void setFromJson(BT::Blackboard& blackboard, const std::string& key, const nlohmann::json& value);

}  // namespace miron::btcpp
