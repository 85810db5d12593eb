#include "decisions.hpp"

#include <iostream>

namespace miron::btcpp
{

void Decisions::setVariant(const std::string& varpoint, const std::string& value)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    variants_[varpoint] = value;
  }
  changed_.notify_all();
}

void Decisions::setBlackboard(const std::string& varpoint, const nlohmann::json& value)
{
  {
    std::lock_guard<std::mutex> lock(mutex_);
    blackboard_[varpoint] = value;
  }
  changed_.notify_all();
}

std::optional<std::string> Decisions::variant(const std::string& varpoint) const
{
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = variants_.find(varpoint);
  if(it == variants_.end())
  {
    return std::nullopt;
  }
  return it->second;
}

bool Decisions::hasVariant(const std::string& varpoint) const
{
  return variants_.count(varpoint) != 0;  // called under waitFor's lock
}

void Decisions::applyTo(BT::Blackboard& blackboard)
{
  std::map<std::string, nlohmann::json> changed;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    auto& applied = applied_[&blackboard];
    for(const auto& [key, value] : blackboard_)
    {
      auto it = applied.find(key);
      if(it == applied.end() || it->second != value)
      {
        applied[key] = value;
        changed[key] = value;
      }
    }
  }
  for(const auto& [key, value] : changed)
  {
    try
    {
      auto entry = blackboard.getEntry(key);
      if(entry && entry->info.type() == typeid(std::string))
      {
        // a string port (skill actions' ports are) created the entry: the number as its text,
        // which the skill action sends as a number again
        blackboard.set(key, value.dump());
      }
      else if(value.is_boolean())
      {
        blackboard.set(key, value.get<bool>());
      }
      else
      {
        blackboard.set(key, value.get<double>());
      }
    }
    catch(const std::exception& e)
    {
      // the tree typed that key otherwise: the decision cannot be written, the tree keeps running
      std::cerr << "miron-btcpp: blackboard decision " << key << " not written: " << e.what() << std::endl;
    }
  }
}

}  // namespace miron::btcpp
