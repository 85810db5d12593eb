#include "nodes.hpp"
#include "runtime.hpp"

namespace miron::btcpp
{

void feedBlackboardOf(const BT::Blackboard::Ptr& blackboard)
{
  if(auto* root = blackboard ? blackboard->rootBlackboard() : nullptr)
  {
    Runtime::instance().decisions().applyTo(*root);
  }
}

VariantAction::VariantAction(const std::string& name, const BT::NodeConfig& config)
  : BT::StatefulActionNode(name, config)
{
  auto varpoint = getInput<std::string>("varpoint");
  if(!varpoint || varpoint->empty())
  {
    throw BT::RuntimeError(name + ": VariantAction needs a varpoint attribute");
  }
  if(config.output_ports.count("value") == 0)
  {
    throw BT::RuntimeError(name + ": VariantAction needs a value port, e.g. value=\"{" + *varpoint + "_sel}\"");
  }
  varpoint_ = *varpoint;
  Runtime::instance().bus();  // subscribe now: the cache's current decision is there before the first tick
}

BT::PortsList VariantAction::providedPorts()
{
  return { BT::InputPort<std::string>("varpoint", "the variation point this node follows"),
           BT::OutputPort<std::string>("value", "the engine's current choice for it") };
}

BT::NodeStatus VariantAction::follow()
{
  feedBlackboardOf(config().blackboard);
  if(auto value = Runtime::instance().decisions().variant(varpoint_))
  {
    setOutput("value", *value);
  }
  return BT::NodeStatus::RUNNING;
}

BT::NodeStatus VariantAction::onStart()
{
  return follow();
}

BT::NodeStatus VariantAction::onRunning()
{
  return follow();
}

}  // namespace miron::btcpp
