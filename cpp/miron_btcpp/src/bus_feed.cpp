#include "bus_feed.hpp"

#include <zmq.h>

#include <iostream>
#include <vector>

namespace miron::btcpp
{

namespace
{
const std::string VARIANT_PREFIX = "miron.variant.";
const std::string BLACKBOARD_PREFIX = "miron.blackboard.";

bool endsWith(const std::string& text, const std::string& suffix)
{
  return text.size() >= suffix.size() &&
         text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

bool startsWith(const std::string& text, const std::string& prefix)
{
  return text.compare(0, prefix.size(), prefix) == 0;
}
}  // namespace

BusFeed::BusFeed(void* zmq_context, std::string endpoint, Decisions& decisions)
  : context_(zmq_context), endpoint_(std::move(endpoint)), decisions_(decisions)
{}

BusFeed::~BusFeed()
{
  stop();
}

void BusFeed::start()
{
  if(running_.exchange(true))
  {
    return;
  }
  thread_ = std::thread([this] { loop(); });
}

void BusFeed::stop()
{
  running_ = false;
  if(thread_.joinable())
  {
    thread_.join();
  }
}

void BusFeed::loop()
{
  void* sub = zmq_socket(context_, ZMQ_SUB);
  int linger = 0;
  zmq_setsockopt(sub, ZMQ_LINGER, &linger, sizeof(linger));
  int timeout = 100;
  zmq_setsockopt(sub, ZMQ_RCVTIMEO, &timeout, sizeof(timeout));
  zmq_setsockopt(sub, ZMQ_SUBSCRIBE, VARIANT_PREFIX.data(), VARIANT_PREFIX.size());
  zmq_setsockopt(sub, ZMQ_SUBSCRIBE, BLACKBOARD_PREFIX.data(), BLACKBOARD_PREFIX.size());
  if(zmq_connect(sub, endpoint_.c_str()) != 0)
  {
    std::cerr << "miron-btcpp: cannot connect to the bus at " << endpoint_ << ": "
              << zmq_strerror(zmq_errno()) << std::endl;
    zmq_close(sub);
    return;
  }
  while(running_)
  {
    std::vector<std::string> frames;
    int more = 1;
    while(more)
    {
      zmq_msg_t msg;
      zmq_msg_init(&msg);
      if(zmq_msg_recv(&msg, sub, 0) < 0)
      {
        zmq_msg_close(&msg);
        break;
      }
      frames.emplace_back(static_cast<const char*>(zmq_msg_data(&msg)), zmq_msg_size(&msg));
      more = zmq_msg_more(&msg);
      zmq_msg_close(&msg);
    }
    if(frames.empty())
    {
      continue;
    }
    if(frames.size() != 2)
    {
      reject("a message of " + std::to_string(frames.size()) + " frames on " + frames[0]);
      continue;
    }
    onMessage(frames[0], frames[1]);
  }
  zmq_close(sub);
}

void BusFeed::reject(const std::string& why)
{
  rejected++;
  std::cerr << "miron-btcpp: dropped a malformed decision: " << why << std::endl;
}

void BusFeed::onMessage(const std::string& topic, const std::string& body)
{
  // the same checks as the Java executor's DecisionFeed
  auto message = nlohmann::json::parse(body, nullptr, false);
  if(message.is_discarded() || !message.is_object() || !message.contains("varpoint") ||
     !message["varpoint"].is_string() || !message.contains("value") || message["value"].is_null())
  {
    reject("not a decision on " + topic);
    return;
  }
  const auto varpoint = message["varpoint"].get<std::string>();
  const auto& value = message["value"];
  if(!endsWith(topic, "." + varpoint))
  {
    reject("varpoint " + varpoint + " on " + topic);
    return;
  }
  if(startsWith(topic, VARIANT_PREFIX))
  {
    decisions_.setVariant(varpoint, value.is_string() ? value.get<std::string>() : value.dump());
  }
  else if(value.is_number() || value.is_boolean())
  {
    decisions_.setBlackboard(varpoint, value);
  }
  else
  {
    reject("a blackboard decision that is neither a number nor a boolean on " + topic);
    return;
  }
  accepted++;
}

}  // namespace miron::btcpp
