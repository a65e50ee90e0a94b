#include "rtamp/exec/perception_errors.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "rtamp/exec/subtree_builder.hpp"
#include "rtamp/util/error.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/world/geometry.hpp"

namespace rtamp::exec {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kTimeTolerance = 1e-9;

void check_time(const char* name, double v) {
  if (!std::isfinite(v) || v < 0)
    throw Error(std::string("perception errors: ") + name + " must be a finite number of seconds >= 0, found " +
                format_number(v));
}

}  // namespace

double PerceptionErrors::longest() const {
  double d = delay;
  if (late_probability > 0) d = std::max(d, late_delay);
  if (false_removal_rate > 0) d = std::max(d, false_removal_duration);
  return d;
}

PerceptionErrors camera_perception_errors(std::uint64_t seed) {
  PerceptionErrors e;
  e.delay = 0.36;
  e.late_probability = 0.21;
  e.late_delay = 2.0;
  e.seed = seed;
  return e;
}

void check(const PerceptionErrors& e) {
  check_time("delay", e.delay);
  check_time("late_delay", e.late_delay);
  check_time("false_removal_duration", e.false_removal_duration);
  if (!std::isfinite(e.false_removal_rate) || e.false_removal_rate < 0)
    throw Error("perception errors: false_removal_rate must be a finite rate >= 0 (per thing and second), found " +
                format_number(e.false_removal_rate));
  if (!(e.late_probability >= 0 && e.late_probability <= 1))
    throw Error("perception errors: late_probability must be in [0, 1], found " + format_number(e.late_probability));
}

PerceptionErrorWorld::PerceptionErrorWorld(World& inner, const world::Scenario& s, PerceptionErrors errors)
    : ForwardingWorld(inner), errors_(errors), rng_(errors.seed ^ 0x7065726365707431ull), next_false_removal_(kInf) {
  check(errors_);
  for (const auto& r : s.regions) regions_.insert(r.name);
  shown_ = inner_.observe();
  schedule_false_removal(inner_.time());
}

PerceptionErrorWorld::PerceptionErrorWorld(std::unique_ptr<World> inner, const world::Scenario& s,
                                           PerceptionErrors errors)
    : PerceptionErrorWorld(*inner, s, errors) {
  owned_ = std::move(inner);
}

double PerceptionErrorWorld::next_event_time() const {
  const double inner = inner_.next_event_time();
  if (!std::isfinite(inner)) return inner;  // a world that cannot tell is ticked
  double t = std::min(inner, next_false_removal_);
  for (const auto& [name, due] : due_) t = std::min(t, due);
  for (const auto& [name, until] : hidden_) t = std::min(t, until);
  return t;
}

// A Poisson process at the rate per thing times the things shown now.
void PerceptionErrorWorld::schedule_false_removal(double now) {
  const double rate = errors_.false_removal_rate * static_cast<double>(shown_.things.size());
  next_false_removal_ = rate > 0 ? now - std::log1p(-rng_.unit()) / rate : kInf;
}

bool PerceptionErrorWorld::robots_own(const std::string& name, const world::Placement& truth) const {
  if (!started_ || name != move_.thing) return false;
  const std::string* now = truth.location_of(name);
  const std::string* was = shown_.location_of(name);
  // Into the gripper, or out of it (the gripper knows when it lets go).
  return (was && *was == kInHand) || (now && *now == kInHand);
}

void PerceptionErrorWorld::show(const std::string& name, const world::Placement& truth) {
  if (auto it = truth.things.find(name); it != truth.things.end()) {
    shown_.things[name] = it->second;
  } else {
    shown_.things.erase(name);
  }
  due_.erase(name);
}

// A change shown before another it depends on (a thing in a container not shown
// yet; a container gone with things still shown in it) brings that one forward.
void PerceptionErrorWorld::make_consistent(const world::Placement& truth) {
  for (bool changed = true; changed;) {
    changed = false;
    for (const auto& [name, thing] : shown_.things) {
      const std::string& at = thing.location;
      if (at == kInHand || at == world::kNoLocation || regions_.count(at)) continue;
      const auto c = shown_.things.find(at);
      if (c != shown_.things.end() && c->second.container && at != name) continue;
      const std::string who = name, where = at;  // show() changes the map
      show(where, truth);
      show(who, truth);
      changed = true;
      break;
    }
  }
}

void PerceptionErrorWorld::update(const world::Placement& truth) {
  const double now = inner_.time();
  double batch_due = -1;  // the changes noticed together show together
  const auto notice = [&](const std::string& name) {
    const auto t = truth.things.find(name);
    const auto s = shown_.things.find(name);
    if (t != truth.things.end() && s != shown_.things.end() && t->second == s->second) {
      due_.erase(name);
    } else if (robots_own(name, truth)) {
      show(name, truth);
    } else if (!due_.count(name)) {
      if (batch_due < 0)
        batch_due = now + (rng_.unit() < errors_.late_probability ? errors_.late_delay : errors_.delay);
      due_[name] = batch_due;
    }
  };
  for (const auto& [name, thing] : truth.things) notice(name);
  // Shown but no longer true (gone): collected first, since show() would change shown_.
  gone_.clear();
  for (const auto& [name, thing] : shown_.things)
    if (!truth.things.count(name)) gone_.push_back(name);
  for (const std::string& name : gone_) notice(name);
  for (auto it = due_.begin(); it != due_.end();) {
    const std::string name = it->first;
    ++it;
    if (due_.at(name) <= now + kTimeTolerance) show(name, truth);
  }
  make_consistent(truth);
}

world::Placement PerceptionErrorWorld::observe() {
  const world::Placement truth = inner_.observe();
  const double now = inner_.time();
  update(truth);
  std::erase_if(hidden_, [&](const auto& h) { return h.second <= now + kTimeTolerance || !shown_.things.count(h.first); });
  while (next_false_removal_ <= now + kTimeTolerance) {
    std::vector<std::string> eligible;
    for (const auto& [name, thing] : shown_.things) {
      const bool resting = thing.location != kInHand && thing.location != world::kNoLocation;
      if (!thing.container && resting && !hidden_.count(name) && !(started_ && name == move_.thing))
        eligible.push_back(name);
    }
    if (!eligible.empty()) hidden_[eligible[rng_.below(eligible.size())]] = now + errors_.false_removal_duration;
    schedule_false_removal(next_false_removal_);
  }
  world::Placement out = shown_;
  for (const auto& [name, until] : hidden_) out.things.erase(name);
  differs_ = out != truth;
  return out;
}

bool PerceptionErrorWorld::confirming() const {
  const double now = inner_.time();
  for (const auto& [name, due] : due_)
    if (due <= now + errors_.delay + kTimeTolerance) return true;
  return inner_.confirming();
}

void PerceptionErrorWorld::start(const Move& m) {
  const world::Placement truth = inner_.observe();
  // The arm goes to the thing and to where it goes, and sees what is there.
  for (const std::string& name : {m.thing, m.to})
    if (due_.count(name)) show(name, truth);
  make_consistent(truth);
  hidden_.erase(m.thing);
  move_ = m;
  started_ = true;
  inner_.start(m);
}

}  // namespace rtamp::exec
