#include "skill_client.hpp"

#include <zmq.h>

#include <iostream>
#include <vector>

namespace miron::btcpp
{

namespace
{
using Clock = std::chrono::steady_clock;

std::vector<std::string> receiveAll(void* socket)
{
  std::vector<std::string> frames;
  int more = 1;
  while(more)
  {
    zmq_msg_t msg;
    zmq_msg_init(&msg);
    if(zmq_msg_recv(&msg, socket, ZMQ_DONTWAIT) < 0)
    {
      zmq_msg_close(&msg);
      break;
    }
    frames.emplace_back(static_cast<const char*>(zmq_msg_data(&msg)), zmq_msg_size(&msg));
    more = zmq_msg_more(&msg);
    zmq_msg_close(&msg);
  }
  return frames;
}

void* dealer(void* context, const std::string& endpoint)
{
  void* socket = zmq_socket(context, ZMQ_DEALER);
  int linger = 0;
  zmq_setsockopt(socket, ZMQ_LINGER, &linger, sizeof(linger));
  zmq_connect(socket, endpoint.c_str());
  return socket;
}
}  // namespace

SkillClient::SkillClient(void* zmq_context, std::string requests, std::string results,
                         long deadline_ms, long ack_timeout_ms)
  : context_(zmq_context)
  , requests_endpoint_(std::move(requests))
  , results_endpoint_(std::move(results))
  , deadline_ms_(deadline_ms)
  , ack_timeout_ms_(ack_timeout_ms)
  // ids start from the clock so that two runs never reuse an id the interface may still know
  , next_id_(std::chrono::duration_cast<std::chrono::milliseconds>(
                 std::chrono::system_clock::now().time_since_epoch())
                     .count() *
                 1000)
{}

SkillClient::~SkillClient()
{
  stop(std::chrono::milliseconds(0));
}

void SkillClient::start()
{
  if(running_.exchange(true))
  {
    return;
  }
  thread_ = std::thread([this] { loop(); });
}

void SkillClient::stop(std::chrono::milliseconds wait)
{
  if(!thread_.joinable())
  {
    return;
  }
  drain_until_ = Clock::now() + wait;
  draining_ = true;
  thread_.join();
}

long SkillClient::push(const std::string& skill, const nlohmann::json& in_attributes)
{
  long id = next_id_++;
  nlohmann::json message = { { "id", id },
                             { "msg-type", "push-skill" },
                             { "skill",
                               { { "name", skill },
                                 { "skill-definition-fqn", skill },
                                 { "in-attribute", in_attributes },
                                 { "out-attribute", nlohmann::json::object() } } } };
  std::lock_guard<std::mutex> lock(mutex_);
  pending_[id] = Pending{ skill, Clock::now() + std::chrono::milliseconds(deadline_ms_), false, std::nullopt };
  outbox_.push_back(Request{ id, message.dump() });
  return id;
}

std::optional<SkillOutcome> SkillClient::poll(long id)
{
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = pending_.find(id);
  if(it == pending_.end())
  {
    return SkillOutcome{ false, "ABORT", nlohmann::json::object() };
  }
  if(!it->second.outcome)
  {
    return std::nullopt;
  }
  SkillOutcome outcome = *it->second.outcome;
  pending_.erase(it);
  return outcome;
}

std::string SkillClient::abortMessage()
{
  nlohmann::json message = { { "id", next_id_++ },
                             { "msg-type", "query" },
                             { "query", { { "type", "abort-current-skill" } } } };
  return message.dump();
}

void SkillClient::abort(long id)
{
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = pending_.find(id);
  if(it == pending_.end())
  {
    return;
  }
  bool sent = it->second.sent;
  bool done = it->second.outcome.has_value();
  pending_.erase(it);  // a held push is then skipped by the sender
  if(sent && !done)
  {
    // aborts go first: the robot must stop what the tree gave up before anything else
    outbox_.push_front(Request{ 0, abortMessage() });
  }
}

void SkillClient::onResult(const std::string& frame)
{
  auto message = nlohmann::json::parse(frame, nullptr, false);
  if(message.is_discarded() || !message.is_object() || !message.contains("msg-type") ||
     message["msg-type"] != "skill-result" || !message.contains("id") ||
     !message["id"].is_number_integer())
  {
    malformed++;
    std::cerr << "miron-btcpp: ignored a message on the skill-result socket that is not a skill-result"
              << std::endl;
    return;
  }
  long id = message["id"].get<long>();
  std::string result = "ERROR";
  if(message.contains("result") && message["result"].is_object() &&
     message["result"].contains("result") && message["result"]["result"].is_string())
  {
    result = message["result"]["result"].get<std::string>();
  }
  nlohmann::json outputs = nlohmann::json::object();
  if(message.contains("outputs") && message["outputs"].is_object())
  {
    outputs = message["outputs"];
  }
  std::lock_guard<std::mutex> lock(mutex_);
  auto it = pending_.find(id);
  if(it == pending_.end() || it->second.outcome)
  {
    return;  // a skill of another client, or one given up
  }
  it->second.outcome = SkillOutcome{ result == "SUCCESS", result, outputs };
}

void SkillClient::failSent(const std::string& why)
{
  std::lock_guard<std::mutex> lock(mutex_);
  for(auto& [id, p] : pending_)
  {
    if(p.sent && !p.outcome)
    {
      p.outcome = SkillOutcome{ false, why, nlohmann::json::object() };
      failed_by_fault++;
      std::cerr << "miron-btcpp: skill " << p.skill << " failed: " << why << std::endl;
    }
  }
}

void SkillClient::expireDeadlines()
{
  std::lock_guard<std::mutex> lock(mutex_);
  auto now = Clock::now();
  for(auto& [id, p] : pending_)
  {
    if(!p.outcome && now >= p.deadline)
    {
      p.outcome = SkillOutcome{ false, "no result within " + std::to_string(deadline_ms_) + " ms",
                                nlohmann::json::object() };
      failed_by_fault++;
      std::cerr << "miron-btcpp: skill " << p.skill << " failed: " << p.outcome->result << std::endl;
      if(p.sent)
      {
        outbox_.push_front(Request{ 0, abortMessage() });
      }
    }
  }
}

void SkillClient::loop()
{
  void* sub = zmq_socket(context_, ZMQ_SUB);
  int linger = 0;
  zmq_setsockopt(sub, ZMQ_LINGER, &linger, sizeof(linger));
  zmq_setsockopt(sub, ZMQ_SUBSCRIBE, "", 0);
  // the results link: up after a handshake, down on a disconnection
  std::string monitor_endpoint = "inproc://miron-btcpp-results-" + std::to_string(reinterpret_cast<uintptr_t>(this));
  zmq_socket_monitor(sub, monitor_endpoint.c_str(), ZMQ_EVENT_HANDSHAKE_SUCCEEDED | ZMQ_EVENT_DISCONNECTED);
  void* monitor = zmq_socket(context_, ZMQ_PAIR);
  zmq_setsockopt(monitor, ZMQ_LINGER, &linger, sizeof(linger));
  zmq_connect(monitor, monitor_endpoint.c_str());
  if(zmq_connect(sub, results_endpoint_.c_str()) != 0)
  {
    std::cerr << "miron-btcpp: cannot connect to the skill results at " << results_endpoint_ << std::endl;
  }
  void* requests = dealer(context_, requests_endpoint_);
  bool link_up = false;
  std::optional<Request> in_flight;
  Clock::time_point sent_at;
  int attempts = 0;

  while(true)
  {
    if(draining_)
    {
      bool idle;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        idle = outbox_.empty();
      }
      if((idle && !in_flight) || Clock::now() >= drain_until_)
      {
        break;
      }
    }
    zmq_pollitem_t items[] = { { sub, 0, ZMQ_POLLIN, 0 },
                               { requests, 0, ZMQ_POLLIN, 0 },
                               { monitor, 0, ZMQ_POLLIN, 0 } };
    zmq_poll(items, 3, 20);
    if(items[2].revents & ZMQ_POLLIN)
    {
      auto frames = receiveAll(monitor);
      if(!frames.empty() && frames[0].size() >= 2)
      {
        uint16_t event = *reinterpret_cast<const uint16_t*>(frames[0].data());
        if(event == ZMQ_EVENT_HANDSHAKE_SUCCEEDED)
        {
          link_up = true;
        }
        else if(event == ZMQ_EVENT_DISCONNECTED && link_up)
        {
          link_up = false;
          failSent("the skill interface went away (results connection lost); its result is lost");
        }
      }
    }
    if(items[0].revents & ZMQ_POLLIN)
    {
      for(auto frames = receiveAll(sub); !frames.empty(); frames = receiveAll(sub))
      {
        onResult(frames.back());
      }
    }
    if(items[1].revents & ZMQ_POLLIN)
    {
      receiveAll(requests);  // the ack: an empty frame behind REQ's empty delimiter
      in_flight.reset();
      attempts = 0;
    }
    if(in_flight && Clock::now() - sent_at > std::chrono::milliseconds(ack_timeout_ms_))
    {
      // no ack: drop the socket (and any stale reply with it) and send again on a new one
      zmq_close(requests);
      requests = dealer(context_, requests_endpoint_);
      attempts++;
      std::cerr << "miron-btcpp: no ack from the skill interface, retry " << attempts << std::endl;
      bool still_wanted = true;
      if(in_flight->push_id != 0)
      {
        std::lock_guard<std::mutex> lock(mutex_);
        auto it = pending_.find(in_flight->push_id);
        still_wanted = it != pending_.end() && !it->second.outcome;
      }
      if(!still_wanted || draining_)
      {
        in_flight.reset();
      }
      else
      {
        zmq_send(requests, "", 0, ZMQ_SNDMORE);
        zmq_send(requests, in_flight->body.data(), in_flight->body.size(), 0);
        sent_at = Clock::now();
      }
    }
    if(!in_flight)
    {
      std::lock_guard<std::mutex> lock(mutex_);
      while(!outbox_.empty())
      {
        Request next = outbox_.front();
        if(next.push_id != 0)
        {
          auto it = pending_.find(next.push_id);
          if(it == pending_.end() || it->second.outcome)
          {
            outbox_.pop_front();  // aborted or failed before it was sent
            continue;
          }
          if(!link_up || draining_)
          {
            break;  // held until the results link is up
          }
          it->second.sent = true;
          pushed++;
        }
        else
        {
          aborted++;
        }
        outbox_.pop_front();
        zmq_send(requests, "", 0, ZMQ_SNDMORE);
        zmq_send(requests, next.body.data(), next.body.size(), 0);
        sent_at = Clock::now();
        in_flight = next;
        break;
      }
    }
    expireDeadlines();
  }
  zmq_socket_monitor(sub, nullptr, 0);
  zmq_close(monitor);
  zmq_close(sub);
  zmq_close(requests);
}

}  // namespace miron::btcpp
