// MIRoN's BehaviorTree.CPP 4 plugin: runs MIRoN-woven trees on the real BehaviorTree.CPP.
//
//   factory.registerFromPlugin("libmiron_btcpp.so");          // VariantAction (+ MIRON_BTCPP_TREES' skills)
//   miron::btcpp::registerSkillActions(factory, "tree.ext.xml"); // every other action: push-skill
//   auto tree = factory.createTreeFromFile("tree.ext.xml");
//   while (...) { miron::btcpp::feedBlackboard(tree); tree.tickOnce(); tree.sleep(50ms); }
//
// VariantAction follows the engine's miron.variant.<vp> decisions on the broker's bus (ZeroMQ SUB
// on its XPUB, the last-value cache gives the current decision at start); miron.blackboard.<vp>
// numbers and booleans are written to the root blackboard under the varpoint's name; every action
// the tree declares or uses is a skill pushed to the SmartSoft skill interface (docs/wire-formats.md).
// Endpoints come from configure() or the environment (MIRON_BUS, MIRON_SKILL_REQUESTS,
// MIRON_SKILL_RESULTS), loopback defaults. See docs/btcpp-plugin.md.
#pragma once

#include <behaviortree_cpp/bt_factory.h>

#include <chrono>
#include <map>
#include <optional>
#include <set>
#include <string>

namespace miron::btcpp
{

/** Where the plugin connects. */
struct Endpoints
{
  std::string bus = "tcp://127.0.0.1:5561";             ///< the broker's XPUB (bus out)
  std::string skill_requests = "tcp://127.0.0.1:5556";  ///< the broker's ROUTER (request path)
  std::string skill_results = "tcp://127.0.0.1:5558";   ///< the skill interface's PUB
  long skill_deadline_ms = 120000;                      ///< a pushed skill without result fails after this
  long ack_timeout_ms = 2000;                           ///< a request without ack is sent again after this

  /** The defaults overridden by MIRON_BUS, MIRON_SKILL_REQUESTS, MIRON_SKILL_RESULTS, MIRON_SKILL_DEADLINE_MS. */
  static Endpoints fromEnvironment();
};

/** Sets the endpoints; only before the first node connects (later calls are ignored, with a warning). */
void configure(const Endpoints& endpoints);

/**
 * Registers a skill action (push-skill, RUNNING until skill-result, aborted on halt) for every
 * action the tree file (and what it includes) declares in <TreeNodesModel> or uses, except those
 * already registered. Returns the IDs registered. Throws BT::RuntimeError when the file cannot be read.
 */
std::set<std::string> registerSkillActions(BT::BehaviorTreeFactory& factory, const std::string& tree_file);

/** Copies changed miron.blackboard.<vp> decisions into the tree's root blackboard; call before each tick. */
void feedBlackboard(BT::Tree& tree);

/** The varpoints of the tree's VariantAction nodes. */
std::set<std::string> followedVarpoints(const BT::Tree& tree);

/** Waits until every varpoint has a decision (from the bus or set by hand); false on timeout. */
bool awaitDecisions(const std::set<std::string>& varpoints, std::chrono::milliseconds timeout);

/** Starts the bus subscriber now (it starts with the first VariantAction otherwise). */
void connectBus();

/** Decisions by hand (tests, scripted runs): what a miron.variant.<vp> / miron.blackboard.<vp> message would set. */
void setVariant(const std::string& varpoint, const std::string& value);

/** Counters for logs and tests. */
struct Counters
{
  long decisions = 0;          ///< accepted miron.variant / miron.blackboard messages
  long rejected_decisions = 0; ///< malformed ones (logged and dropped)
  long pushed = 0;             ///< push-skill requests sent
  long aborted = 0;            ///< abort-current-skill requests sent
  long malformed_results = 0;  ///< messages on the results socket that were not skill results
  long failed_by_fault = 0;    ///< skills failed because of a deadline or a lost results link
};
Counters counters();

/** Halts nothing; stops the plugin's threads, sending the queued aborts first (at most wait). */
void shutdown(std::chrono::milliseconds wait = std::chrono::milliseconds(1000));

}  // namespace miron::btcpp
