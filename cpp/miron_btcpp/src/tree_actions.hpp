// The actions a tree file declares or uses, with their port names (read with tinyxml2).
#pragma once

#include <behaviortree_cpp/bt_factory.h>

#include <map>
#include <set>
#include <string>

namespace miron::btcpp
{

struct ActionPorts
{
  std::set<std::string> inputs;
  std::set<std::string> outputs;
  std::set<std::string> inouts;
};

/** Every action of the file and its includes not registered in the factory, by ID. */
std::map<std::string, ActionPorts> actionsOf(const BT::BehaviorTreeFactory& factory, const std::string& tree_file);

/** An action manifest with these ports (any type). */
BT::TreeNodeManifest manifestOf(const std::string& id, const ActionPorts& ports);

}  // namespace miron::btcpp
