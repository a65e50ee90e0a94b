#include "rtamp/serve/hub.hpp"

#include <algorithm>
#include <string_view>

#include <nlohmann/json.hpp>

namespace rtamp::serve {

using nlohmann::json;

namespace {
std::shared_ptr<const std::string> share(std::string s) { return std::make_shared<const std::string>(std::move(s)); }

// A `log` message around a record; the history keeps the messages (one copy of a record, shared).
constexpr std::string_view kLogHead = "{\"type\":\"log\",\"record\":";
std::shared_ptr<const std::string> log_message(const std::string& record) {
  std::string m;
  m.reserve(kLogHead.size() + record.size() + 1);
  m += kLogHead;
  m += record;
  m += '}';
  return share(std::move(m));
}
std::string_view record_of(const std::string& log_message) {
  return std::string_view(log_message).substr(kLogHead.size(), log_message.size() - kLogHead.size() - 1);
}

// The body of a tree message: the message without "type" (hello's `tree`).
std::string tree_body(const std::string& tree_message) {
  if (tree_message.empty()) return "null";
  json j = json::parse(tree_message);
  j.erase("type");
  return j.dump();
}
}  // namespace

std::string state_message(const PlaybackState& s) {
  return json{{"type", "state"}, {"speed", s.speed}, {"paused", s.paused}, {"t", s.t}, {"ended", s.ended}}.dump();
}

Hub::Hub(std::string hello_fields) : fields_(std::move(hello_fields)) {}

std::string Hub::hello_locked() const {
  std::string h = "{\"type\":\"hello\",\"protocol\":1,";
  h += fields_.substr(1, fields_.size() - 2);
  h += ",\"speed\":" + json(state_.speed).dump() + ",\"paused\":" + (state_.paused ? "true" : "false") +
       ",\"t\":" + json(state_.t).dump() + ",\"ended\":" + (state_.ended ? "true" : "false");
  h += ",\"tree\":" + tree_body(tree_);
  h += ",\"history\":[";
  std::size_t size = h.size() + 2;
  for (const auto& m : history_) size += m->size() - kLogHead.size();
  h.reserve(size);
  for (std::size_t i = 0; i < history_.size(); ++i) {
    if (i) h += ',';
    h += record_of(*history_[i]);
  }
  h += "]}";
  return h;
}

std::string Hub::hello() const {
  std::lock_guard lock(mu_);
  return hello_locked();
}

void Hub::join(const std::shared_ptr<Client>& c) {
  std::lock_guard lock(mu_);
  c->send(share(hello_locked()), false);
  if (!frame_.empty()) c->send(share(frame_), true);
  clients_.push_back(c);
  count_.store(clients_.size());
}

void Hub::leave(const Client* c) {
  std::lock_guard lock(mu_);
  clients_.erase(std::remove_if(clients_.begin(), clients_.end(), [c](const auto& p) { return p.get() == c; }),
                 clients_.end());
  count_.store(clients_.size());
}

void Hub::clear() {
  std::vector<std::shared_ptr<Client>> gone;
  {
    std::lock_guard lock(mu_);
    gone.swap(clients_);
    count_.store(0);
  }
}

void Hub::broadcast_locked(const std::shared_ptr<const std::string>& m, bool frame) {
  for (const auto& c : clients_) c->send(m, frame);
}

void Hub::log_record(const std::string& record) {
  std::lock_guard lock(mu_);
  history_.push_back(log_message(record));
  if (!clients_.empty()) broadcast_locked(history_.back(), false);
}

void Hub::tree(const std::string& message) {
  std::lock_guard lock(mu_);
  tree_ = message;
  if (!clients_.empty()) broadcast_locked(share(message), false);
}

void Hub::status(const std::string& message) {
  std::lock_guard lock(mu_);
  if (!clients_.empty()) broadcast_locked(share(message), false);
}

void Hub::frame(const std::string& message) {
  std::lock_guard lock(mu_);
  frame_ = message;
  if (!clients_.empty()) broadcast_locked(share(message), true);
}

void Hub::state(const PlaybackState& s) {
  std::lock_guard lock(mu_);
  state_ = s;
  if (!clients_.empty()) broadcast_locked(share(state_message(s)), false);
}

PlaybackState Hub::state() const {
  std::lock_guard lock(mu_);
  return state_;
}

void Hub::time(double t) {
  std::lock_guard lock(mu_);
  state_.t = t;
}

std::size_t Hub::history_size() const {
  std::lock_guard lock(mu_);
  return history_.size();
}

void Hub::reset(std::vector<std::string> history, std::string tree, std::string frame, const PlaybackState& s) {
  std::lock_guard lock(mu_);
  history_.clear();
  history_.reserve(history.size());
  for (const std::string& r : history) history_.push_back(log_message(r));
  tree_ = std::move(tree);
  frame_ = std::move(frame);
  state_ = s;
  if (clients_.empty()) return;
  broadcast_locked(share(hello_locked()), false);
  if (!frame_.empty()) broadcast_locked(share(frame_), true);
}

}  // namespace rtamp::serve
