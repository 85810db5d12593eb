// The plugin's process-wide state: one ZeroMQ context, the decisions, the bus feed and the skill
// client, created on first use with the configured (or environment's) endpoints. Nodes are made by
// the factory without access to anything else, so they find these here.
#pragma once

#include "bus_feed.hpp"
#include "decisions.hpp"
#include "miron_btcpp/miron_btcpp.hpp"
#include "skill_client.hpp"

#include <memory>
#include <mutex>

namespace miron::btcpp
{

class Runtime
{
public:
  static Runtime& instance();
  void configure(const Endpoints& endpoints);
  Decisions& decisions() { return decisions_; }
  /** The bus subscriber, started on first use. */
  BusFeed& bus();
  /** The skill client, started on first use. */
  SkillClient& skills();
  Counters counters();
  void shutdown(std::chrono::milliseconds wait);

private:
  Runtime();
  std::mutex mutex_;
  Endpoints endpoints_;
  bool connected_ = false;
  void* context_ = nullptr;
  Decisions decisions_;
  std::unique_ptr<BusFeed> bus_;
  std::unique_ptr<SkillClient> skills_;
};

}  // namespace miron::btcpp
