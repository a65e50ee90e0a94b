#include "rtamp/serve/replay.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <map>
#include <utility>

#include <nlohmann/json.hpp>

#include "rtamp/automata/translate.hpp"
#include "rtamp/ltl/parser.hpp"
#include "rtamp/serve/frame.hpp"
#include "rtamp/episode/log_check.hpp"
#include "rtamp/serve/detail/logged_tree.hpp"
#include "rtamp/serve/scene_message.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/world/geometry.hpp"

namespace rtamp::serve {

using nlohmann::json;

namespace {

// What an added thing is: a container?, its class (from the `intervention` record that added it).
using Added = std::map<std::string, std::pair<bool, std::string>>;

// A placement record's {"name": "location"} as a Placement: classes of things
// added by interventions from their records, else the scenario's, else as before, else "block".
world::Placement placement_of(const json& j, const world::Scenario& s, const Added& added,
                              const world::Placement& before) {
  world::Placement p;
  for (const auto& [name, loc] : j.items()) {
    if (!loc.is_string()) continue;
    std::string cls = "block";
    bool container = false;
    if (auto a = added.find(name); a != added.end()) {
      container = a->second.first;
      cls = a->second.second;
    } else if (const auto* c = s.find_container(name)) {
      cls = c->cls;
      container = true;
    } else if (const auto* o = s.find_object(name)) {
      cls = o->cls;
    } else if (auto it = before.things.find(name); it != before.things.end()) {
      cls = it->second.cls;
      container = it->second.container;
    }
    p.set(name, loc.get<std::string>(), cls, container);
  }
  return p;
}

}  // namespace

Replay::Replay(const world::Scenario& scenario, const std::string& path, ReplayOptions options)
    : scenario_(scenario), layout_(scenario), playback_(options.speed, options.paused) {
  world::Placement last = world::initial_placement(scenario);
  std::string world_name = "symbolic";
  Added added;
  LoggedTree tree(scenario);
  auto each = [&](const json& j, const std::string&, int n) {
    Record r;
    r.t = j["t"].get<double>();
    r.text = j.dump();
    const std::string ev = j["ev"].get<std::string>();
    r.frame = ev == "frame";
    if (ev == "episode") {
      world_name = j.value("world", "symbolic");
      const std::string sc = j.value("scenario", "");
      if (!sc.empty() && sc != scenario.name)
        throw Error("the log is of scenario '" + sc + "', not '" + scenario.name + "'", SourceLocation{path, n, 0});
    }
    if (ev == "intervention" && j.value("applied", false)) {
      const std::string kind = j.value("kind", "");
      // Logs before the record carried "class": the kind's default class.
      if (kind == "add" || kind == "add-container")
        added[j.value("subject", "")] = {kind == "add-container",
                                         j.value("class", kind == "add-container" ? "tray" : "block")};
    }
    const char* key = ev == "perceived" || ev == "end" ? "placement" : ev == "run" ? "state" : nullptr;
    if (key && j.contains(key) && j[key].is_object()) {
      world::Placement p = placement_of(j[key], scenario, added, last);
      r.placement = p;
      last = std::move(p);
    }
    if (auto m = tree.record(j, r.t, last)) r.tree = std::move(*m);
    r.statuses_only = ev == "statuses";
    if (ev == "statuses" || ev == "end")
      if (const auto st = j.find(ev == "end" ? "statuses" : "s"); st != j.end() && st->is_string())
        r.statuses = st->get<std::string>();
    // The latest frame, placement and tree up to this record (kNone: none yet).
    const std::size_t i = records_.size();
    const Record* before = records_.empty() ? nullptr : &records_.back();
    r.last_frame = r.frame ? i : before ? before->last_frame : kNone;
    r.last_placement = r.placement ? i : before ? before->last_placement : kNone;
    r.last_tree = !r.tree.empty() ? i : before ? before->last_tree : kNone;
    r.last_statuses = !r.statuses.empty() ? i : before ? before->last_statuses : kNone;
    records_.push_back(std::move(r));
  };
  try {  // the one check of every log reader (episode/log_check.hpp), then each record
    episode::read_episode_log(path, &scenario, each);
  } catch (const Error& e) {
    throw Error(std::string("--replay: ") + e.what());
  }
  duration_ = records_.back().t;
  home_ = {scenario.robot.base[0], scenario.robot.base[1], scenario.robot.base[2] + 0.5};
  const automata::Automaton ba = automata::translate(ltl::parse(scenario.task, scenario.task_where));
  hub_ = std::make_unique<Hub>(hello_fields(scenario, ba, "replay", world_name, duration_));
  PlaybackState s;
  s.speed = options.speed;
  s.paused = options.paused;
  hub_->reset({}, "", "", frame_at(0), s);
}

Replay::~Replay() {
  stop();
}

std::size_t Replay::first_after(double t) const {
  const auto it = std::upper_bound(records_.begin(), records_.end(), t + 1e-9,
                                   [](double x, const Record& r) { return x < r.t; });
  return static_cast<std::size_t>(it - records_.begin());
}

std::string Replay::frame_at(double t) {
  const std::size_t end = first_after(t);
  const std::size_t frame = end > 0 ? records_[end - 1].last_frame : kNone;
  const std::size_t placed = end > 0 ? records_[end - 1].last_placement : kNone;
  if (frame != kNone) {
    json j = json::parse(frame_message_from_record(records_[frame].text));
    j["t"] = t;
    // A later placement (e.g. the end record's) gives the things' locations.
    if (placed != kNone && placed > frame)
      for (auto& th : j["things"])
        if (const std::string* loc = records_[placed].placement->location_of(th.value("name", ""))) th["at"] = *loc;
    return j.dump();
  }
  const world::Placement p = placed != kNone ? *records_[placed].placement : world::initial_placement(scenario_);
  layout_ = exec::ThingLayout(scenario_);
  return frame_message(layout_.frame(t, p, home_));
}

void Replay::publish(double t) {
  PlaybackState s;
  s.speed = playback_.speed();
  s.paused = playback_.paused();
  s.t = t;
  s.ended = ended_.load();
  hub_->state(s);
}

void Replay::seek_to(double t) {
  t = std::clamp(t, 0.0, duration_);
  ++seeks_;
  t_ = t;
  next_ = first_after(t);
  std::vector<std::string> history;
  history.reserve(next_);
  for (std::size_t i = 0; i < next_; ++i)
    if (!records_[i].frame && !records_[i].statuses_only) history.push_back(records_[i].text);
  // The tree at t: the latest change up to t; its statuses: the latest logged since that change.
  std::string tree, statuses;
  if (next_ > 0 && records_[next_ - 1].last_tree != kNone) {
    const Record& r = records_[next_ - 1];
    tree = records_[r.last_tree].tree;
    if (r.last_statuses != kNone && r.last_statuses >= r.last_tree) statuses = records_[r.last_statuses].statuses;
  }
  ended_.store(next_ >= records_.size());
  PlaybackState s;
  s.speed = playback_.speed();
  s.paused = playback_.paused();
  s.t = t;
  s.ended = ended_.load();
  hub_->reset(std::move(history), std::move(tree), std::move(statuses), frame_at(t), s);
}

void Replay::run() {
  auto service = [this] {
    const double s = seek_.exchange(-1);
    if (s >= 0) seek_to(s);
  };
  auto last_frame = std::chrono::steady_clock::now();
  while (!playback_.stopped()) {
    service();
    if (next_ >= records_.size()) {  // at the end: wait for a seek or stop
      if (!ended_.exchange(true)) publish(t_);
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    const bool step = playback_.hold(service);
    if (playback_.stopped()) break;
    service();
    if (next_ >= records_.size()) continue;
    const double speed = playback_.speed();
    double target = (step || speed <= 0) ? records_[next_].t : std::min(records_[next_].t, t_ + speed / 30);
    const std::uint64_t seeks = seeks_;
    if (!step) playback_.pace(target, service);
    // A seek while pacing moved t_ and next_: `target` is stale (going on would snap forward).
    if (seek_.load() >= 0 || seeks_ != seeks) continue;
    t_ = std::max(t_, target);
    bool sent = false;
    while (next_ < records_.size() && records_[next_].t <= t_ + 1e-9) {
      const Record& r = records_[next_];
      if (!r.frame && !r.statuses_only) hub_->log_record(r.text, false);  // sent with the frame below
      if (!r.tree.empty()) hub_->tree(r.tree);
      if (!r.statuses.empty() && r.last_tree != kNone) hub_->status(r.t, r.statuses);
      ++next_;
      sent = true;
    }
    const auto now = std::chrono::steady_clock::now();
    if (sent || now - last_frame > std::chrono::milliseconds(33)) {
      hub_->frame(t_, frame_at(t_));
      last_frame = now;
    }
    if (step) publish(t_);
  }
}

void Replay::start() {
  thread_ = std::thread([this] { run(); });
}

void Replay::stop() {
  playback_.stop();
  if (thread_.joinable()) thread_.join();
}

void Replay::handle(const Request& r, Reply reply) {
  if (r.type == Request::Type::Invalid) {
    reply(reply_message(r.id, false, r.error));
    return;
  }
  if (r.type == Request::Type::Intervene) {
    reply(reply_message(r.id, false, "this is a replay: interventions change nothing (run `rtamp serve` live)"));
    return;
  }
  if (r.type == Request::Type::Task) {
    reply(reply_message(r.id, false, "this is a replay: its task changes are the log's (run `rtamp serve` live)"));
    return;
  }
  const std::string& a = r.action;
  if (a == "speed" && !(*r.value >= 0 && *r.value <= 1000)) {
    reply(reply_message(r.id, false, "speed must be in [0, 1000] (0: as fast as possible)"));
    return;
  }
  if (a == "seek") {
    if (!(*r.value >= 0)) {
      reply(reply_message(r.id, false, "seek needs a time >= 0"));
      return;
    }
    seek_.store(*r.value);
    playback_.wake();
  }
  if (a == "pause") playback_.pause();
  if (a == "resume") playback_.resume();
  if (a == "step") {
    if (!playback_.paused()) {
      reply(reply_message(r.id, false, "step needs the replay paused"));
      return;
    }
    playback_.step();
  }
  if (a == "speed") playback_.set_speed(*r.value);
  reply(reply_message(r.id, true));
  if (a != "seek") {
    PlaybackState s = hub_->state();
    s.speed = playback_.speed();
    s.paused = playback_.paused();
    hub_->state(s);
  }
}

}  // namespace rtamp::serve
