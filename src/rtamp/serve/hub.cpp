#include "rtamp/serve/hub.hpp"

#include <algorithm>
#include <optional>
#include <string_view>

#include <nlohmann/json.hpp>

#include "rtamp/serve/tree_message.hpp"

namespace rtamp::serve {

using nlohmann::json;

namespace {
std::shared_ptr<const std::string> share(std::string s) { return std::make_shared<const std::string>(std::move(s)); }

// The start of a `log` message; its records follow, comma-separated, then "]}".
constexpr std::string_view kLogHead = "{\"type\":\"log\",\"records\":[";

// The body of a tree message: the message without "type" (hello's `tree`),
// its nodes' statuses replaced by `statuses` (one character a node) if any.
std::string tree_body(const std::string& tree_message, const std::string& statuses) {
  if (tree_message.empty()) return "null";
  json j = json::parse(tree_message);
  j.erase("type");
  json& nodes = j["nodes"];
  if (statuses.size() == nodes.size())
    for (std::size_t i = 0; i < statuses.size(); ++i) nodes[i]["status"] = status_name(statuses[i]);
  return j.dump();
}
// The `"task":..,"automaton":..` members of hello for a record that puts a task in
// force (an `episode` record with its automaton, an applied `task` record), else none.
std::optional<std::string> task_members(const std::string& record) {
  if (record.find("\"ev\":\"task\"") == std::string::npos && record.find("\"ev\":\"episode\"") == std::string::npos)
    return std::nullopt;  // the quick test: most records are neither
  const json j = json::parse(record, nullptr, false);
  if (!j.is_object()) return std::nullopt;
  const auto ev = j.find("ev"), task = j.find("task"), automaton = j.find("automaton");
  if (ev == j.end() || !ev->is_string() || task == j.end() || !task->is_string() || automaton == j.end() ||
      !automaton->is_object())
    return std::nullopt;
  const auto applied = j.find("applied");
  const bool in_force = *ev == "episode" || (*ev == "task" && applied != j.end() && *applied == true);
  if (!in_force) return std::nullopt;
  const std::string members = json{{"task", *task}, {"automaton", *automaton}}.dump(-1, ' ', false, json::error_handler_t::replace);
  return members.substr(1, members.size() - 2);
}

}  // namespace

std::string state_message(const PlaybackState& s) {
  return json{{"type", "state"}, {"speed", s.speed}, {"paused", s.paused}, {"t", s.t}, {"ended", s.ended}}.dump();
}

Hub::Hub(std::string hello_fields) {
  // The task and automaton are the task in force, kept apart from the fixed members.
  json fields = json::parse(hello_fields);
  const json first{{"task", fields.value("task", "")}, {"automaton", fields.value("automaton", json::object())}};
  fields.erase("task");
  fields.erase("automaton");
  fields_ = fields.dump(-1, ' ', false, json::error_handler_t::replace);
  first_task_ = first.dump(-1, ' ', false, json::error_handler_t::replace);
  first_task_ = first_task_.substr(1, first_task_.size() - 2);
  task_ = first_task_;
}

std::string Hub::hello_locked() const {
  std::string h = "{\"type\":\"hello\",\"protocol\":2,";
  h += fields_.substr(1, fields_.size() - 2);
  h += ',';
  h += task_;
  h += ",\"speed\":" + json(state_.speed).dump() + ",\"paused\":" + (state_.paused ? "true" : "false") +
       ",\"t\":" + json(state_.t).dump() + ",\"ended\":" + (state_.ended ? "true" : "false");
  h += ",\"tree\":" + tree_body(tree_, statuses_);
  h += ",\"history\":[";
  std::size_t size = h.size() + 2;
  for (const auto& r : history_) size += r.size() + 1;
  h.reserve(size);
  for (std::size_t i = 0; i < history_.size(); ++i) {
    if (i) h += ',';
    h += history_[i];
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
  flush_locked();  // the new client's hello has these records
  c->send(share(hello_locked()), Slot::None);
  if (!frame_.empty()) c->send(share(frame_), Slot::Frame);
  if (camera_) c->send(camera_, Slot::Camera);
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

void Hub::broadcast_locked(const std::shared_ptr<const std::string>& m, Slot slot) {
  for (const auto& c : clients_) c->send(m, slot);
}

void Hub::log_record(const std::string& record, bool urgent) {
  std::lock_guard lock(mu_);
  history_.push_back(record);
  if (auto task = task_members(record)) task_ = std::move(*task);
  if (clients_.empty()) return;
  batch_ += batch_.empty() ? kLogHead : std::string_view(",");
  batch_ += record;
  if (urgent) flush_locked();
}

void Hub::flush_locked() {
  if (batch_.empty()) return;
  batch_ += "]}";
  auto m = share(std::move(batch_));
  batch_.clear();
  if (!clients_.empty()) broadcast_locked(m, Slot::None);
}

void Hub::flush() {
  std::lock_guard lock(mu_);
  flush_locked();
}

void Hub::tree(const std::string& message) {
  std::lock_guard lock(mu_);
  flush_locked();
  tree_ = message;
  statuses_.clear();
  if (!clients_.empty()) broadcast_locked(share(message), Slot::None);
}

void Hub::status(double t, const std::string& statuses) {
  std::lock_guard lock(mu_);
  flush_locked();
  statuses_ = statuses;
  if (!clients_.empty()) broadcast_locked(share(status_message(t, statuses)), Slot::None);
}

void Hub::frame(double t, const std::string& message, bool broadcast) {
  std::lock_guard lock(mu_);
  frame_ = message;
  state_.t = t;
  if (!broadcast || clients_.empty()) return;
  flush_locked();
  broadcast_locked(share(message), Slot::Frame);
}

void Hub::camera(std::string message) {
  auto m = share(std::move(message));
  std::lock_guard lock(mu_);
  flush_locked();
  camera_ = m;
  if (!clients_.empty()) broadcast_locked(m, Slot::Camera);
}

void Hub::state(const PlaybackState& s) {
  std::lock_guard lock(mu_);
  flush_locked();
  state_ = s;
  if (!clients_.empty()) broadcast_locked(share(state_message(s)), Slot::None);
}

PlaybackState Hub::state() const {
  std::lock_guard lock(mu_);
  return state_;
}

std::size_t Hub::history_size() const {
  std::lock_guard lock(mu_);
  return history_.size();
}

void Hub::reset(std::vector<std::string> history, std::string tree, std::string statuses, std::string frame,
                const PlaybackState& s) {
  std::lock_guard lock(mu_);
  batch_.clear();  // the new hello has the history
  history_ = std::move(history);
  task_ = first_task_;
  for (const auto& r : history_)
    if (auto task = task_members(r)) task_ = std::move(*task);
  tree_ = std::move(tree);
  statuses_ = std::move(statuses);
  frame_ = std::move(frame);
  state_ = s;
  if (clients_.empty()) return;
  broadcast_locked(share(hello_locked()), Slot::None);
  if (!frame_.empty()) broadcast_locked(share(frame_), Slot::Frame);
}

}  // namespace rtamp::serve
