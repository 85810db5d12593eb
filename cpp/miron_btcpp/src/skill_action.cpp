#include "nodes.hpp"
#include "runtime.hpp"
#include "values.hpp"

#include <iostream>

namespace miron::btcpp
{

SkillAction::SkillAction(const std::string& name, const BT::NodeConfig& config, std::string skill,
                         std::set<std::string> output_ports)
  : BT::StatefulActionNode(name, config), skill_(std::move(skill)), output_ports_(std::move(output_ports))
{
  Runtime::instance().skills();  // connect now, so the results link is up by the first push
}

BT::NodeStatus SkillAction::onStart()
{
  feedBlackboardOf(config().blackboard);
  nlohmann::json in = nlohmann::json::object();
  for(const auto& [port, raw] : config().input_ports)
  {
    if(output_ports_.count(port) != 0)
    {
      continue;
    }
    BT::StringView key;
    if(isBlackboardPointer(raw, &key))
    {
      std::string name = key == "=" ? port : std::string(key);
      auto entry = config().blackboard->getEntry(name);
      if(!entry || entry->value.empty())
      {
        // never sent: BehaviorTree.CPP's getInput fails the same way (docs/bt-semantics.md)
        std::cerr << "miron-btcpp: " << fullPath() << ": skill " << skill_ << " not pushed: port " << port
                  << "=\"" << raw << "\" reads blackboard key '" << name << "', which has no value"
                  << std::endl;
        return BT::NodeStatus::FAILURE;
      }
      std::unique_lock<std::mutex> lock(entry->entry_mutex);
      in[port] = toJson(entry->value);
    }
    else
    {
      in[port] = toScalar(raw);
    }
  }
  last_in_ = in.dump();
  running_ = Runtime::instance().skills().push(skill_, in);
  return BT::NodeStatus::RUNNING;
}

BT::NodeStatus SkillAction::onRunning()
{
  auto outcome = Runtime::instance().skills().poll(running_);
  if(!outcome)
  {
    return BT::NodeStatus::RUNNING;
  }
  running_ = 0;
  for(const auto& [port, value] : outcome->outputs.items())
  {
    std::string raw;
    if(auto it = config().output_ports.find(port); it != config().output_ports.end())
    {
      raw = it->second;
    }
    else if(auto in = config().input_ports.find(port); in != config().input_ports.end())
    {
      raw = in->second;
    }
    BT::StringView key;
    if(isBlackboardPointer(raw, &key))
    {
      try
      {
        setFromJson(*config().blackboard, key == "=" ? port : std::string(key), value);
      }
      catch(const std::exception& e)
      {
        std::cerr << "miron-btcpp: " << fullPath() << ": output " << port << " not written: " << e.what()
                  << std::endl;
      }
    }
  }
  return outcome->success ? BT::NodeStatus::SUCCESS : BT::NodeStatus::FAILURE;
}

void SkillAction::onHalted()
{
  if(running_ != 0)
  {
    Runtime::instance().skills().abort(running_);
    running_ = 0;
  }
}

}  // namespace miron::btcpp
