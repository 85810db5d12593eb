// The latest decision per varpoint, written by the bus thread and read by the ticking thread.
// Only the latest value matters (decisions are state), so a map under a mutex: no queue, no backlog.
#pragma once

#include <behaviortree_cpp/blackboard.h>
#include <behaviortree_cpp/contrib/json.hpp>  // the nlohmann::json BehaviorTree.CPP ships (one copy: no ODR clash)

#include <condition_variable>
#include <map>
#include <mutex>
#include <optional>
#include <string>

namespace miron::btcpp
{

class Decisions
{
public:
  void setVariant(const std::string& varpoint, const std::string& value);
  void setBlackboard(const std::string& varpoint, const nlohmann::json& value);
  std::optional<std::string> variant(const std::string& varpoint) const;
  bool hasVariant(const std::string& varpoint) const;
  /** Waits up to timeout for a change of any decision; false on timeout. */
  template <class Pred>
  bool waitFor(Pred pred, std::chrono::milliseconds timeout)
  {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, timeout, [&] { return pred(); });
  }

  /**
   * Writes the blackboard decisions that changed since the last call for this blackboard, under the
   * varpoint's name (numbers as double, booleans as bool), as the Java executor's BlackboardFeed:
   * only changed values, so the tree may overwrite a key meanwhile.
   */
  void applyTo(BT::Blackboard& blackboard);

private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::map<std::string, std::string> variants_;
  std::map<std::string, nlohmann::json> blackboard_;
  std::map<const BT::Blackboard*, std::map<std::string, nlohmann::json>> applied_;
};

}  // namespace miron::btcpp
