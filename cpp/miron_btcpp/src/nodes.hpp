// The plugin's nodes.
#pragma once

#include <behaviortree_cpp/action_node.h>

#include <set>
#include <string>

namespace miron::btcpp
{

/**
 * <Action ID="VariantAction" varpoint="task" value="{task_sel}"/>: on every tick writes the current
 * decision for its varpoint to its value port, so a Switch reading {task_sel} follows the engine,
 * and stays RUNNING (it monitors, it never finishes). Before the first decision it writes nothing
 * and the Switch takes its default. Also feeds the blackboard decisions (see feedBlackboard), so a
 * tree run by someone else's loop gets them too.
 */
class VariantAction : public BT::StatefulActionNode
{
public:
  VariantAction(const std::string& name, const BT::NodeConfig& config);
  static BT::PortsList providedPorts();
  BT::NodeStatus onStart() override;
  BT::NodeStatus onRunning() override;
  void onHalted() override {}
  const std::string& varpoint() const { return varpoint_; }

private:
  BT::NodeStatus follow();
  std::string varpoint_;
};

/**
 * An action carried out by the skill interface: the first tick pushes the skill named like the
 * action ID with the node's input ports as in-attribute (numbers as numbers), later ticks are
 * RUNNING until its skill-result (SUCCESS → SUCCESS, else FAILURE); halting it aborts the skill.
 * The result's outputs are written to the output ports of the same name. A port whose blackboard
 * key has no value is never sent: the action fails without pushing, as the Java executor does.
 */
class SkillAction : public BT::StatefulActionNode
{
public:
  SkillAction(const std::string& name, const BT::NodeConfig& config, std::string skill,
              std::set<std::string> output_ports);
  BT::NodeStatus onStart() override;
  BT::NodeStatus onRunning() override;
  void onHalted() override;
  const std::string& skill() const { return skill_; }
  /** The in-attribute object of the last push, as JSON text. */
  const std::string& lastInAttributes() const { return last_in_; }

private:
  std::string skill_;
  std::string last_in_;
  std::set<std::string> output_ports_;
  long running_ = 0;
};

/** Copies the blackboard decisions into the root blackboard of the tree whose blackboard this is. */
void feedBlackboardOf(const BT::Blackboard::Ptr& blackboard);

}  // namespace miron::btcpp
