#include "values.hpp"

#include <cerrno>
#include <climits>
#include <cstdlib>
#include <regex>

namespace miron::btcpp
{

nlohmann::json toScalar(const std::string& literal)
{
  auto begin = literal.find_first_not_of(" \t\r\n");
  auto end = literal.find_last_not_of(" \t\r\n");
  std::string text = begin == std::string::npos ? "" : literal.substr(begin, end - begin + 1);
  static const std::regex integer("[-+]?[0-9]+");
  static const std::regex decimal("[-+]?[0-9.]+([eE][-+]?[0-9]+)?");
  if(std::regex_match(text, integer))
  {
    errno = 0;
    long long value = std::strtoll(text.c_str(), nullptr, 10);
    if(errno == 0 && value >= INT_MIN && value <= INT_MAX)  // Java's Integer.parseInt range
    {
      return static_cast<int>(value);
    }
  }
  if(std::regex_match(text, decimal))
  {
    char* rest = nullptr;
    double value = std::strtod(text.c_str(), &rest);
    if(rest && *rest == '\0' && std::isfinite(value))
    {
      return value;
    }
  }
  return literal;
}

nlohmann::json toJson(const BT::Any& value)
{
  if(value.isString())
  {
    return toScalar(value.cast<std::string>());
  }
  if(value.isType<bool>())
  {
    return value.cast<bool>();
  }
  if(value.isIntegral())
  {
    return value.cast<int64_t>();
  }
  if(value.isNumber())
  {
    return value.cast<double>();
  }
  auto text = value.tryCast<std::string>();
  return text ? nlohmann::json(*text) : nlohmann::json(nullptr);
}

void setFromJson(BT::Blackboard& blackboard, const std::string& key, const nlohmann::json& value)
{
  if(value.is_boolean())
  {
    blackboard.set(key, value.get<bool>());
  }
  else if(value.is_number_integer())
  {
    blackboard.set(key, value.get<int64_t>());
  }
  else if(value.is_number())
  {
    blackboard.set(key, value.get<double>());
  }
  else if(value.is_string())
  {
    blackboard.set(key, value.get<std::string>());
  }
  else
  {
    blackboard.set(key, value.dump());
  }
}

}  // namespace miron::btcpp
