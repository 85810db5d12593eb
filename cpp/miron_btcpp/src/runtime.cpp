#include "runtime.hpp"

#include <zmq.h>

#include <cstdlib>
#include <iostream>

namespace miron::btcpp
{

namespace
{
std::string env(const char* name, const std::string& fallback)
{
  const char* value = std::getenv(name);
  return value && *value ? std::string(value) : fallback;
}
}  // namespace

Endpoints Endpoints::fromEnvironment()
{
  Endpoints e;
  e.bus = env("MIRON_BUS", e.bus);
  e.skill_requests = env("MIRON_SKILL_REQUESTS", e.skill_requests);
  e.skill_results = env("MIRON_SKILL_RESULTS", e.skill_results);
  e.skill_deadline_ms = std::atol(env("MIRON_SKILL_DEADLINE_MS", std::to_string(e.skill_deadline_ms)).c_str());
  if(e.skill_deadline_ms <= 0)
  {
    e.skill_deadline_ms = Endpoints().skill_deadline_ms;
  }
  return e;
}

Runtime::Runtime() : endpoints_(Endpoints::fromEnvironment()), context_(zmq_ctx_new())
{}

Runtime& Runtime::instance()
{
  // never destroyed: nodes of trees in static storage may still use it at exit
  static Runtime* runtime = new Runtime();
  return *runtime;
}

void Runtime::configure(const Endpoints& endpoints)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if(bus_ || skills_)
  {
    std::cerr << "miron-btcpp: configure() after the plugin connected is ignored" << std::endl;
    return;
  }
  endpoints_ = endpoints;
}

BusFeed& Runtime::bus()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if(!bus_)
  {
    bus_ = std::make_unique<BusFeed>(context_, endpoints_.bus, decisions_);
    if(!endpoints_.bus.empty())  // empty: decisions only by hand (scripted runs)
    {
      bus_->start();
    }
  }
  return *bus_;
}

SkillClient& Runtime::skills()
{
  std::lock_guard<std::mutex> lock(mutex_);
  if(!skills_)
  {
    skills_ = std::make_unique<SkillClient>(context_, endpoints_.skill_requests, endpoints_.skill_results,
                                            endpoints_.skill_deadline_ms, endpoints_.ack_timeout_ms);
    skills_->start();
  }
  return *skills_;
}

Counters Runtime::counters()
{
  std::lock_guard<std::mutex> lock(mutex_);
  Counters c;
  if(bus_)
  {
    c.decisions = bus_->accepted;
    c.rejected_decisions = bus_->rejected;
  }
  if(skills_)
  {
    c.pushed = skills_->pushed;
    c.aborted = skills_->aborted;
    c.malformed_results = skills_->malformed;
    c.failed_by_fault = skills_->failed_by_fault;
  }
  return c;
}

void Runtime::shutdown(std::chrono::milliseconds wait)
{
  std::lock_guard<std::mutex> lock(mutex_);
  if(skills_)
  {
    skills_->stop(wait);
  }
  if(bus_)
  {
    bus_->stop();
  }
}

}  // namespace miron::btcpp
