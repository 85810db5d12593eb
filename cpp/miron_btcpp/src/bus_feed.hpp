// The engine's decisions from the broker's bus: a SUB on the broker's XPUB subscribed to
// miron.variant. and miron.blackboard., on its own thread. Malformed messages are logged, counted
// and dropped. A restarted broker needs nothing special: libzmq reconnects the SUB and sends its
// subscriptions again, and the new broker replays its last-value cache for them (the engine
// re-announces its decisions to it).
#pragma once

#include "decisions.hpp"

#include <atomic>
#include <string>
#include <thread>

namespace miron::btcpp
{

class BusFeed
{
public:
  BusFeed(void* zmq_context, std::string endpoint, Decisions& decisions);
  ~BusFeed();
  void start();
  void stop();
  /** Handles one message (topic, body); public for the tests of the parsing. */
  void onMessage(const std::string& topic, const std::string& body);

  std::atomic<long> accepted{ 0 };
  std::atomic<long> rejected{ 0 };

private:
  void loop();
  void reject(const std::string& why);

  void* context_;
  std::string endpoint_;
  Decisions& decisions_;
  std::atomic<bool> running_{ false };
  std::thread thread_;
};

}  // namespace miron::btcpp
