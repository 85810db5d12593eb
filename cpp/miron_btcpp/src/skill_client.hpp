// The connection to the SmartSoft skill interface, as the Java executor's ZmqSkillClient speaks it:
// push-skill and abort-current-skill requests go through the broker's request path (a DEALER with
// REQ's envelope, one request in flight, acked by an empty frame, sent again on a new socket when
// the ack does not come: "lazy pirate"), skill-result messages are read from the interface's PUB
// and matched to the pushed skill by id. One thread owns the sockets; the ticking thread only
// touches the maps under a mutex, so a tick never blocks on the network.
//
// A pushed skill fails (its node FAILS, the tree decides) when its deadline passes (an
// abort-current-skill is sent too) or when the results link drops (a PUB keeps nothing for a
// subscriber that is away, so its result is lost). Pushes are sent only while the results link is
// up, so a short skill's result cannot arrive before our SUB is connected.
#pragma once

#include <behaviortree_cpp/contrib/json.hpp>  // the nlohmann::json BehaviorTree.CPP ships (one copy: no ODR clash)

#include <atomic>
#include <chrono>
#include <deque>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <thread>

namespace miron::btcpp
{

struct SkillOutcome
{
  bool success = false;
  std::string result;       ///< SUCCESS, ERROR, ABORT, or why the executor gave up
  nlohmann::json outputs;   ///< the result's "outputs" object
};

class SkillClient
{
public:
  SkillClient(void* zmq_context, std::string requests, std::string results, long deadline_ms,
              long ack_timeout_ms);
  ~SkillClient();
  void start();
  /** Stops the thread after sending what is queued (aborts first of all), waiting at most wait. */
  void stop(std::chrono::milliseconds wait);

  /** Queues a push-skill; the id to poll. */
  long push(const std::string& skill, const nlohmann::json& in_attributes);
  /** The outcome once the result arrived (the skill is then forgotten). */
  std::optional<SkillOutcome> poll(long id);
  /** Gives the skill up: not sent yet, it is dropped; sent, abort-current-skill is sent. */
  void abort(long id);

  std::atomic<long> pushed{ 0 };
  std::atomic<long> aborted{ 0 };
  std::atomic<long> malformed{ 0 };
  std::atomic<long> failed_by_fault{ 0 };

  /** Handles one frame of the results socket; public for tests. */
  void onResult(const std::string& frame);

private:
  struct Pending
  {
    std::string skill;
    std::chrono::steady_clock::time_point deadline;
    bool sent = false;
    std::optional<SkillOutcome> outcome;
  };
  struct Request
  {
    long push_id = 0;  ///< 0: not a push (an abort)
    std::string body;
  };

  void loop();
  void failSent(const std::string& why);
  void expireDeadlines();
  std::string abortMessage();

  void* context_;
  std::string requests_endpoint_;
  std::string results_endpoint_;
  long deadline_ms_;
  long ack_timeout_ms_;
  std::mutex mutex_;
  std::map<long, Pending> pending_;
  std::deque<Request> outbox_;
  std::atomic<long> next_id_;
  std::atomic<bool> running_{ false };
  std::atomic<bool> draining_{ false };
  std::chrono::steady_clock::time_point drain_until_;
  std::thread thread_;
};

}  // namespace miron::btcpp
