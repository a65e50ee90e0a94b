#include "rtamp/world/person.hpp"

#include <algorithm>
#include <cmath>

#include "rtamp/util/error.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/world/space_rules.hpp"

namespace rtamp::world {

namespace {

using Kind = Intervention::Kind;
constexpr double kInf = std::numeric_limits<double>::infinity();

void check(const PersonOptions& o) {
  auto fail = [](const std::string& what, double v) {
    throw Error("person: " + what + ", found " + format_number(v));
  };
  if (!(o.rate >= 0 && std::isfinite(o.rate))) fail("the rate of random interventions must be finite and >= 0 per second", o.rate);
  if (!(o.start >= 0 && std::isfinite(o.start))) fail("the random interventions' start must be finite and >= 0 s", o.start);
  if (!(o.end >= o.start)) fail("the random interventions' end must be >= their start", o.end);
  for (const Intervention& iv : o.script)
    if (!(iv.time >= 0 && std::isfinite(iv.time))) fail("a scripted intervention's time must be finite and >= 0 s", iv.time);
  for (Kind k : o.kinds)
    if (k == Kind::AddRegion) throw Error("person: add-region is a change for the planner, not an intervention");
  if (o.change) {
    if (o.change->kind == Kind::AddRegion) throw Error("person: add-region is a change for the planner, not an intervention");
    if (!(o.change->begin >= 0 && std::isfinite(o.change->begin) && std::isfinite(o.change->end) &&
          o.change->end >= o.change->begin))
      fail("the random change's window must be finite, start at >= 0 s and not end before it begins", o.change->end);
  }
}

}  // namespace

const std::vector<Intervention::Kind>& random_intervention_kinds() {
  static const std::vector<Kind> kinds = PersonOptions{}.kinds;
  return kinds;
}

Person::Person(const Scenario& scenario, PersonOptions options)
    : options_(std::move(options)), scenario_(scenario), rng_(options_.seed * 0x9E3779B97F4A7C15ull + 0x2545F4914F6CDD1Dull) {
  check(options_);
  std::stable_sort(options_.script.begin(), options_.script.end(),
                   [](const Intervention& a, const Intervention& b) { return a.time < b.time; });
  for (const Object& o : scenario.objects) {
    if (std::find(object_classes_.begin(), object_classes_.end(), o.cls) == object_classes_.end())
      object_classes_.push_back(o.cls);
    names_ever_.insert(o.name);
  }
  for (const Container& c : scenario.containers) names_ever_.insert(c.name);
  for (const Region& r : scenario.regions) names_ever_.insert(r.name);
  for (const Intervention& iv : options_.script) names_ever_.insert(iv.subject);
  if (options_.change) {
    const RandomChange& c = *options_.change;
    change_at_ = c.begin + rng_.unit() * (c.end - c.begin);
  }
  if (options_.rate > 0 && !options_.kinds.empty()) schedule_random(0);
}

void Person::schedule_random(double from) {
  const double t = std::max(from, options_.start) - std::log1p(-rng_.unit()) / options_.rate;
  next_random_ = t < options_.end ? t : kInf;
}

double Person::next_time() const {
  {
    std::lock_guard lock(inbox_mutex_);
    if (!inbox_.empty()) return -kInf;
  }
  double t = std::min(next_random_, change_at_);
  if (next_script_ < options_.script.size()) t = std::min(t, options_.script[next_script_].time);
  return t;
}

void Person::post(Intervention iv) {
  std::lock_guard lock(inbox_mutex_);
  inbox_.push_back(std::move(iv));
}

std::optional<Intervention> Person::due(double now, const Placement& truth) {
  {
    std::lock_guard lock(inbox_mutex_);
    if (!inbox_.empty()) {
      Intervention iv = std::move(inbox_.front());
      inbox_.erase(inbox_.begin());
      iv.time = now;
      return iv;
    }
  }
  const double t_script = next_script_ < options_.script.size() ? options_.script[next_script_].time : kInf;
  const double t = std::min({t_script, next_random_, change_at_});
  if (!(t <= now)) return std::nullopt;
  if (t_script == t) {
    Intervention iv = options_.script[next_script_++];
    iv.time = now;
    return iv;
  }
  if (change_at_ == t) {
    change_at_ = kInf;
    return draw(options_.change->kind, now, truth, true);
  }
  const Kind kind = options_.kinds[rng_.below(options_.kinds.size())];
  Intervention iv = draw(kind, now, truth);
  schedule_random(t);
  return iv;
}

std::string Person::target(const std::string& thing, const Body& body, const Placement& truth) {
  std::vector<std::string> all, room;
  const std::string* at = truth.location_of(thing);
  auto consider = [&](const std::string& loc) {
    if (at && *at == loc) return;
    all.push_back(loc);
    if (refusal(thing, body, loc, location_now(scenario_, truth, loc, thing)).empty()) room.push_back(loc);
  };
  for (const Region& r : scenario_.regions) consider(r.name);
  if (!body.container)
    for (const auto& [name, t] : truth.things)
      if (t.container && name != thing && t.location != "hand") consider(name);
  const auto& from = room.empty() ? all : room;
  return from.empty() ? std::string{} : from[rng_.below(from.size())];
}

std::string Person::fresh_name(const Placement& truth) {
  for (;;) {
    std::string n = "x" + std::to_string(++added_);
    if (!names_ever_.count(n) && !truth.things.count(n)) {
      names_ever_.insert(n);
      return n;
    }
  }
}

Intervention Person::draw(Kind kind, double now, const Placement& truth, bool objects_only) {
  Intervention iv;
  iv.time = now;
  iv.kind = kind;
  auto pick = [&](int containers) -> std::string {  // 0 objects, 1 containers, 2 either
    std::vector<std::string> names;
    for (const auto& [n, t] : truth.things)
      if (containers == 2 || t.container == (containers == 1)) names.push_back(n);
    return names.empty() ? std::string{} : names[rng_.below(names.size())];
  };
  auto body = [&](const std::string& n) {
    Body b = body_of(scenario_, n);
    auto it = truth.things.find(n);
    if (it != truth.things.end() && it->second.container != b.container) b = new_body(scenario_, it->second.cls, it->second.container);
    return b;
  };
  switch (kind) {
    case Kind::Relocate:
      iv.subject = pick(objects_only ? 0 : 2);
      iv.location = target(iv.subject, body(iv.subject), truth);
      break;
    case Kind::Add:
      iv.subject = fresh_name(truth);
      iv.cls = object_classes_.empty() ? "block" : object_classes_[rng_.below(object_classes_.size())];
      iv.location = target(iv.subject, new_body(scenario_, iv.cls, false), truth);
      break;
    case Kind::AddContainer: {
      iv.subject = fresh_name(truth);
      iv.cls = scenario_.containers.empty() ? "tray" : scenario_.containers.front().cls;
      iv.capacity = scenario_.containers.empty() ? Container{}.capacity : scenario_.containers.front().capacity;
      iv.location = target(iv.subject, new_body(scenario_, iv.cls, true), truth);
      break;
    }
    case Kind::Remove:
      iv.subject = pick(0);
      break;
    case Kind::RemoveContainer:
      iv.subject = pick(1);
      break;
    case Kind::TakeFromGripper: {
      std::string held;
      for (const auto& [n, t] : truth.things)
        if (t.location == "hand") held = n;
      if (rng_.below(2) && !held.empty()) iv.location = target(held, body(held), truth);
      break;
    }
    case Kind::AddRegion:
      break;  // refused by the constructor
  }
  return iv;
}

}  // namespace rtamp::world
