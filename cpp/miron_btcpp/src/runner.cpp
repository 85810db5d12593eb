// miron-btcpp-run: runs a MIRoN-woven tree on BehaviorTree.CPP 4 with the MIRoN plugin, against a
// live MIRoN installation (broker, engine, skill interface) or a scripted run (--script).
// Prints JSON lines on standard output (start, skill pushes, missions, --trace status changes,
// stop with the plugin's counters); logs go to standard error. Stops cleanly on SIGTERM/SIGINT,
// halting the tree (running skills are aborted on the skill interface).
#include "miron_btcpp/miron_btcpp.hpp"
#include "nodes.hpp"
#include "scripted.hpp"

#include <behaviortree_cpp/loggers/abstract_logger.h>
#include <behaviortree_cpp/loggers/bt_file_logger_v2.h>
#include <behaviortree_cpp/loggers/groot2_publisher.h>
#include <behaviortree_cpp/contrib/json.hpp>  // the nlohmann::json BehaviorTree.CPP ships (one copy: no ODR clash)

#include <atomic>
#include <csignal>
#include <filesystem>
#include <iostream>
#include <memory>
#include <mutex>
#include <string>
#include <unistd.h>

namespace
{
using nlohmann::json;
std::atomic<bool> stop_requested{ false };
std::mutex out_mutex;

void say(const json& line)
{
  std::lock_guard<std::mutex> lock(out_mutex);
  std::cout << line.dump() << std::endl;
}

const char* USAGE =
    "Usage: miron-btcpp-run TREE.xml [options]\n"
    "       miron-btcpp-run --script SCENARIO.json [--plugin PATH]\n"
    "Runs a MIRoN-woven behaviour tree on BehaviorTree.CPP 4 with the MIRoN plugin: VariantAction\n"
    "follows the engine's decisions on the broker's bus, every other action is a skill pushed to the\n"
    "SmartSoft skill interface. Endpoints default to the loopback ports of `miron broker`.\n"
    "  --bus ENDPOINT             the broker's XPUB (default tcp://127.0.0.1:5561)\n"
    "  --skill-requests ENDPOINT  the broker's ROUTER (default tcp://127.0.0.1:5556)\n"
    "  --skill-results ENDPOINT   the skill interface's PUB (default tcp://127.0.0.1:5558)\n"
    "  --skill-deadline MS        a skill without result fails after this (default 120000)\n"
    "  --period MS                time between ticks while RUNNING (default 50)\n"
    "  --decision-wait MS         the first tick waits this long for every varpoint's decision (default 2000)\n"
    "  --repeat                   start the mission again when it ends (until SIGTERM)\n"
    "  --groot PORT               attach BehaviorTree.CPP's Groot2 publisher on PORT (and PORT+1)\n"
    "  --record FILE.btlog        record the run with BehaviorTree.CPP's FileLogger2 (what Groot2 opens)\n"
    "  --plugin PATH              the plugin to load (default: libmiron_btcpp.so next to this program)\n"
    "  --trace                    print every status change as a JSON line\n"
    "  --script SCENARIO.json     scripted run: scripted action results, decisions by tick, no sockets\n";

class JsonTrace : public BT::StatusChangeLogger
{
public:
  JsonTrace(BT::TreeNode* root, bool all) : BT::StatusChangeLogger(root), all_(all) {}
  void callback(BT::Duration, const BT::TreeNode& node, BT::NodeStatus prev, BT::NodeStatus status) override
  {
    auto* skill = dynamic_cast<const miron::btcpp::SkillAction*>(&node);
    if(skill && prev == BT::NodeStatus::IDLE && status == BT::NodeStatus::RUNNING)
    {
      say({ { "event", "skill" }, { "name", skill->skill() }, { "node", node.fullPath() },
            { "in", json::parse(skill->lastInAttributes(), nullptr, false) } });
    }
    if(all_)
    {
      say({ { "event", "status" }, { "node", node.fullPath() }, { "id", node.registrationName() },
            { "from", BT::toStr(prev) }, { "to", BT::toStr(status) } });
    }
  }
  void flush() override {}

private:
  bool all_;
};

std::string defaultPlugin(const char* argv0)
{
  std::error_code ec;
  auto self = std::filesystem::read_symlink("/proc/self/exe", ec);
  auto dir = ec ? std::filesystem::path(argv0).parent_path() : self.parent_path();
  return (dir / "libmiron_btcpp.so").string();
}

int usage(const std::string& message)
{
  std::cerr << "miron-btcpp-run: " << message << "\n" << USAGE;
  return 2;
}
}  // namespace

int main(int argc, char** argv)
{
  miron::btcpp::Endpoints endpoints = miron::btcpp::Endpoints::fromEnvironment();
  std::string tree_file, script, record, plugin = defaultPlugin(argv[0]);
  long period = 50, decision_wait = 2000;
  int groot = 0;
  bool repeat = false, trace = false;
  for(int i = 1; i < argc; i++)
  {
    std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc)
      {
        throw std::invalid_argument(arg + " needs a value");
      }
      return argv[++i];
    };
    try
    {
      if(arg == "-h" || arg == "--help")
      {
        std::cout << USAGE;
        return 0;
      }
      else if(arg == "--bus") endpoints.bus = value();
      else if(arg == "--skill-requests") endpoints.skill_requests = value();
      else if(arg == "--skill-results") endpoints.skill_results = value();
      else if(arg == "--skill-deadline") endpoints.skill_deadline_ms = std::stol(value());
      else if(arg == "--period") period = std::stol(value());
      else if(arg == "--decision-wait") decision_wait = std::stol(value());
      else if(arg == "--groot") groot = std::stoi(value());
      else if(arg == "--plugin") plugin = value();
      else if(arg == "--record") record = value();
      else if(arg == "--script") script = value();
      else if(arg == "--repeat") repeat = true;
      else if(arg == "--trace") trace = true;
      else if(!arg.empty() && arg[0] == '-') return usage("unknown option " + arg);
      else if(tree_file.empty()) tree_file = arg;
      else return usage("one tree only");
    }
    catch(const std::exception& e)
    {
      return usage(std::string("bad value for ") + arg + ": " + e.what());
    }
  }
  if(!script.empty() && !record.empty())
  {
    return usage("--record records a live run, not a --script one");
  }
  if(!script.empty())
  {
    try
    {
      return miron::btcpp::runScripted(script, plugin);
    }
    catch(const std::exception& e)
    {
      std::cerr << "miron-btcpp-run: error: " << e.what() << std::endl;
      return 1;
    }
  }
  if(tree_file.empty())
  {
    return usage("no tree given");
  }
  if(period <= 0 || endpoints.skill_deadline_ms <= 0 || decision_wait < 0 || groot < 0 || groot > 65534)
  {
    return usage("--period and --skill-deadline must be positive, --groot a port");
  }
  std::signal(SIGTERM, [](int) { stop_requested = true; });
  std::signal(SIGINT, [](int) { stop_requested = true; });

  tree_file = std::filesystem::absolute(tree_file).string();  // BT.CPP resolves includes from its folder
  miron::btcpp::configure(endpoints);
  BT::BehaviorTreeFactory factory;
  BT::Tree tree;
  std::set<std::string> skills;
  try
  {
    factory.registerFromPlugin(plugin);
    skills = miron::btcpp::registerSkillActions(factory, tree_file);
    tree = factory.createTreeFromFile(tree_file);
  }
  catch(const std::exception& e)
  {
    std::cerr << tree_file << ": error: " << e.what() << std::endl;
    return 1;
  }
  // FileLogger2 before anything ticks: the recording's clock starts with its header
  std::unique_ptr<BT::FileLogger2> recorder;
  if(!record.empty())
  {
    try
    {
      recorder = std::make_unique<BT::FileLogger2>(tree, record);
    }
    catch(const std::exception& e)
    {
      std::cerr << "miron-btcpp-run: error: cannot record into " << record << ": " << e.what() << std::endl;
      return 2;
    }
  }
  JsonTrace json_trace(tree.rootNode(), trace);
  std::unique_ptr<BT::Groot2Publisher> groot_publisher;
  if(groot > 0)
  {
    groot_publisher = std::make_unique<BT::Groot2Publisher>(tree, groot);
  }
  auto varpoints = miron::btcpp::followedVarpoints(tree);
  miron::btcpp::connectBus();
  // a running engine has the current decisions in the broker's cache: do not start the nominal
  // behaviour for the few milliseconds they take to arrive (the Java executor waits the same way)
  bool decided = miron::btcpp::awaitDecisions(varpoints, std::chrono::milliseconds(decision_wait));
  say({ { "event", "start" }, { "tree", tree_file }, { "varpoints", varpoints }, { "skills", skills },
        { "decisions", decided }, { "groot", groot }, { "record", record }, { "pid", getpid() } });

  while(!stop_requested)
  {
    miron::btcpp::feedBlackboard(tree);
    BT::NodeStatus status;
    try
    {
      status = tree.tickOnce();
    }
    catch(const std::exception& e)
    {
      std::cerr << "miron-btcpp-run: the tree failed: " << e.what() << std::endl;
      say({ { "event", "error" }, { "message", e.what() } });
      break;
    }
    if(status != BT::NodeStatus::RUNNING)
    {
      say({ { "event", "mission" }, { "status", BT::toStr(status) } });
      if(!repeat)
      {
        break;
      }
    }
    tree.sleep(std::chrono::milliseconds(period));
  }
  tree.haltTree();  // aborts the running skills
  miron::btcpp::shutdown(std::chrono::milliseconds(2000));
  auto c = miron::btcpp::counters();
  say({ { "event", "stop" },
        { "counters",
          { { "decisions", c.decisions }, { "rejectedDecisions", c.rejected_decisions }, { "pushed", c.pushed },
            { "aborted", c.aborted }, { "malformedResults", c.malformed_results },
            { "failedByFault", c.failed_by_fault } } } });
  return 0;
}
