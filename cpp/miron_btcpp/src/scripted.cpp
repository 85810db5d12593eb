#include "scripted.hpp"
#include "miron_btcpp/miron_btcpp.hpp"
#include "tree_actions.hpp"

#include <behaviortree_cpp/action_node.h>
#include <behaviortree_cpp/contrib/json.hpp>  // the nlohmann::json BehaviorTree.CPP ships (one copy: no ODR clash)

#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <vector>

namespace miron::btcpp
{

namespace
{
using nlohmann::json;

struct Script
{
  std::vector<std::string> statuses;
  size_t next = 0;
  std::string take()
  {
    return statuses[std::min(next++, statuses.size() - 1)];
  }
};

class ScriptedAction : public BT::StatefulActionNode
{
public:
  ScriptedAction(const std::string& name, const BT::NodeConfig& config, std::shared_ptr<Script> script,
                 std::vector<std::string>* trace)
    : BT::StatefulActionNode(name, config), script_(std::move(script)), trace_(trace)
  {}
  BT::NodeStatus onStart() override { return record("start"); }
  BT::NodeStatus onRunning() override { return record("run"); }
  void onHalted() override { trace_->push_back(name() + ":halt"); }

private:
  BT::NodeStatus record(const std::string& phase)
  {
    std::string status = script_->take();
    trace_->push_back(name() + ":" + phase + ":" + status);
    return BT::convertFromString<BT::NodeStatus>(status);
  }
  std::shared_ptr<Script> script_;
  std::vector<std::string>* trace_;
};
}  // namespace

int runScripted(const std::string& scenario_file, const std::string& plugin)
{
  std::ifstream in(scenario_file);
  json scenario = json::parse(in, nullptr, false);
  if(scenario.is_discarded() || !scenario.is_object() || !scenario.contains("tree"))
  {
    std::cerr << scenario_file << ": error: not a scenario (a JSON object with \"tree\")" << std::endl;
    return 2;
  }
  auto tree_file = std::filesystem::absolute(std::filesystem::absolute(scenario_file).parent_path() /
                                             scenario["tree"].get<std::string>()).string();
  std::vector<std::string> trace;
  Endpoints offline;
  offline.bus = "";  // decisions come from the script only
  configure(offline);
  BT::BehaviorTreeFactory factory;
  factory.registerFromPlugin(plugin);
  auto ports = actionsOf(factory, tree_file);
  const json actions = scenario.value("actions", json::object());
  for(const auto& [id, statuses] : actions.items())
  {
    auto script = std::make_shared<Script>();
    script->statuses = statuses.get<std::vector<std::string>>();
    factory.registerBuilder(manifestOf(id, ports[id]),
                            [script, &trace](const std::string& name, const BT::NodeConfig& config) {
                              return std::make_unique<ScriptedAction>(name, config, script, &trace);
                            });
  }
  BT::Tree tree;
  try
  {
    tree = factory.createTreeFromFile(tree_file);
  }
  catch(const std::exception& e)
  {
    std::cout << json{ { "tick", 0 }, { "error", e.what() } }.dump() << std::endl;
    return 0;
  }
  bool exactly_once = scenario.value("mode", "once") == "exactly_once";
  json variants = scenario.value("variants", json::object());
  int ticks = scenario.value("ticks", 1);
  for(int n = 1; n <= ticks; n++)
  {
    trace.clear();
    const json decided = variants.value(std::to_string(n), json::object());
    for(const auto& [vp, value] : decided.items())
    {
      setVariant(vp, value.is_string() ? value.get<std::string>() : value.dump());
    }
    BT::NodeStatus status;
    try
    {
      feedBlackboard(tree);
      status = exactly_once ? tree.tickExactlyOnce() : tree.tickOnce();
    }
    catch(const std::exception& e)
    {
      std::cout << json{ { "tick", n }, { "error", e.what() }, { "trace", trace } }.dump() << std::endl;
      return 0;
    }
    json values = json::object();
    const auto keys = scenario.value("blackboard", std::vector<std::string>{});
    for(const auto& key : keys)
    {
      values[key] = nullptr;
      if(auto entry = tree.rootBlackboard()->getEntry(key); entry && !entry->value.empty())
      {
        if(auto text = entry->value.tryCast<std::string>())
        {
          values[key] = *text;
        }
      }
    }
    std::cout << json{ { "tick", n }, { "status", BT::toStr(status) }, { "trace", trace }, { "blackboard", values } }.dump()
              << std::endl;
  }
  return 0;
}

}  // namespace miron::btcpp
