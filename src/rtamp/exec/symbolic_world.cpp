#include "rtamp/exec/symbolic_world.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "rtamp/exec/subtree_builder.hpp"
#include "rtamp/task/transition_system.hpp"
#include "rtamp/util/error.hpp"

namespace rtamp::exec {

namespace {

using Kind = world::Intervention::Kind;

constexpr double kTimeSlack = 1e-9;  // events this close after the target time are due

double distance(const world::Vec3& a, const world::Vec3& b) {
  const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

world::Vec3 lerp(const world::Vec3& a, const world::Vec3& b, double f) {
  return {a[0] + (b[0] - a[0]) * f, a[1] + (b[1] - a[1]) * f, a[2] + (b[2] - a[2]) * f};
}

// "none" is a target only where a position falls outside every location.
bool loose_ok(const world::Intervention& iv, const std::string& to) {
  return iv.location.empty() && to == world::kNoLocation;
}

bool holding_phase(Phase p) { return p == Phase::Carry || p == Phase::Place || p == Phase::Return; }

void check(const SymbolicWorldOptions& o) {
  for (double d : {o.approach_base, o.grasp, o.carry_base, o.place, o.retreat, o.return_base})
    if (!(d >= 0 && std::isfinite(d))) throw Error("symbolic world: phase durations must be finite and >= 0");
  if (!(o.speed > 0 && std::isfinite(o.speed))) throw Error("symbolic world: speed must be finite and > 0");
  if (!(o.failure_probability >= 0 && o.failure_probability <= 1))
    throw Error("symbolic world: failure_probability must be in [0, 1]");
  if (o.fails_in != Phase::Approach && o.fails_in != Phase::Grasp && o.fails_in != Phase::Carry &&
      o.fails_in != Phase::Place)
    throw Error("symbolic world: fails_in must be approach, grasp, carry or place");
  if (o.added_container_capacity < 1) throw Error("symbolic world: added_container_capacity must be >= 1");
}

}  // namespace

const NameTable<Phase>& phases() {
  static const NameTable<Phase> t = {
      {"idle", Phase::Idle, "no move"},
      {"approach", Phase::Approach, "the hand goes to the thing"},
      {"grasp", Phase::Grasp, "the gripper closes on it"},
      {"carry", Phase::Carry, "the thing goes to its destination"},
      {"place", Phase::Place, "the thing is set down"},
      {"retreat", Phase::Retreat, "the empty hand backs off"},
      {"return", Phase::Return, "a held thing is carried back and put down after a failure or a halt"},
  };
  return t;
}

const char* to_string(Phase p) { return name_of(phases(), p); }

SymbolicWorld::SymbolicWorld(const world::Scenario& scenario, SymbolicWorldOptions options)
    : options_(std::move(options)), regions_(scenario.regions), geometry_(scenario), table_(world::table_top(scenario)) {
  check(options_);
  for (const auto& c : scenario.containers) {
    ContainerInfo info{c.cls, c.capacity, c.size};
    containers_[c.name] = info;
    container_order_.push_back(c.name);
    class_is_container_[c.cls] = true;
    class_template_.emplace(c.cls, info);
  }
  for (const auto& o : scenario.objects) {
    class_is_container_.emplace(o.cls, false);
    class_object_size_.emplace(o.cls, o.size);
    object_size_[o.name] = o.size;
  }
  placement_ = world::initial_placement(scenario);
  for (const auto& o : scenario.objects)
    if (placement_.things[o.name].location == world::kNoLocation) loose_[o.name] = o.position;
  for (const auto& c : scenario.containers)
    if (placement_.things[c.name].location == world::kNoLocation) loose_[c.name] = c.position;
  for (const auto& loc : location_names())
    if (count_at(loc, "") > capacity(loc))
      throw Error("scenario " + scenario.name + ": " + loc + " starts with more things than its capacity " +
                  std::to_string(capacity(loc)));
  // Footprint rules broken here are accepted (as task::System accepts them) until the thing moves.
  for (const auto& [name, t] : placement_.things)
    if (t.location != world::kNoLocation) unmoved_.insert(name);

  const auto& base = scenario.robot.base;
  home_ = {base[0], base[1], base[2] + options_.home_height};
  hand_point_ = home_;

  // The failures' seeded stream (portable).
  fail_rng_ = SplitMix64(options_.seed * 0x9E3779B97F4A7C15ull + 0x632BE59BD9B4E019ull);
  layout_ = std::make_unique<ThingLayout>(scenario);
}

Frame SymbolicWorld::frame(const world::Placement&) { return layout_->frame(time_, placement_, hand_point()); }

// ---------------------------------------------------------------- locations

bool SymbolicWorld::is_region(const std::string& loc) const {
  return std::any_of(regions_.begin(), regions_.end(), [&](const world::Region& r) { return r.name == loc; });
}

std::vector<std::string> SymbolicWorld::location_names() const {
  std::vector<std::string> out;
  for (const auto& r : regions_) out.push_back(r.name);
  out.insert(out.end(), container_order_.begin(), container_order_.end());
  return out;
}

int SymbolicWorld::capacity(const std::string& location) const {
  for (const auto& r : regions_)
    if (r.name == location) return r.capacity;
  auto it = containers_.find(location);
  return it == containers_.end() ? -1 : it->second.capacity;
}

int SymbolicWorld::count_at(const std::string& loc, const std::string& except) const {
  int n = 0;
  for (const auto& [name, t] : placement_.things)
    if (t.location == loc && name != except) ++n;
  return n;
}

std::int64_t SymbolicWorld::used_at(const std::string& loc, const std::string& except) const {
  std::int64_t n = 0;
  for (const auto& [name, t] : placement_.things)
    if (t.location == loc && name != except) n += cell_of(body_of(name), loc);
  return n;
}

// ---------------------------------------------------------------- footprint rules
// The rule book's (world/space_rules.hpp) cells and rooms, the integers
// task::System's fit tables hold (transition_system.cpp, build_fit_tables):
// the tests check that both agree on every thing and location.

SymbolicWorld::Body SymbolicWorld::body_of(const std::string& thing) const {
  if (auto c = containers_.find(thing); c != containers_.end()) return {c->second.size, true};
  if (auto o = object_size_.find(thing); o != object_size_.end()) return {o->second, false};
  return {};
}

SymbolicWorld::Body SymbolicWorld::new_body(const std::string& cls, bool container) const {
  if (container) {
    auto t = class_template_.find(cls);
    return {t != class_template_.end() ? t->second.size : world::Container{}.size, true};
  }
  auto o = class_object_size_.find(cls);
  return {o != class_object_size_.end() ? o->second : world::Object{}.size, false};
}

world::Extent SymbolicWorld::usable(const std::string& loc) const {
  for (const auto& r : regions_)
    if (r.name == loc) return world::usable_extent(r);
  world::Container c;
  c.size = containers_.at(loc).size;
  return world::usable_extent(c, options_.fit);
}

std::int64_t SymbolicWorld::cell_of(const Body& b, const std::string& loc) const {
  return world::cell_units(b, usable(loc), is_container(loc), options_.fit);
}

bool SymbolicWorld::fits(const std::string& thing, const std::string& location) const {
  if (!placement_.things.count(thing) || (!is_region(location) && !is_container(location))) return false;
  return world::fits(body_of(thing).size, usable(location));
}

std::int64_t SymbolicWorld::cell(const std::string& thing, const std::string& location) const {
  if (!placement_.things.count(thing) || (!is_region(location) && !is_container(location))) return -1;
  return cell_of(body_of(thing), location);
}

std::int64_t SymbolicWorld::room(const std::string& location) const {
  return is_region(location) || is_container(location) ? world::kRoomUnits : -1;
}

std::int64_t SymbolicWorld::used(const std::string& location) const {
  return is_region(location) || is_container(location) ? used_at(location, "") : -1;
}

std::string SymbolicWorld::refusal(const std::string& thing, const std::string& location) const {
  if (!placement_.things.count(thing)) return "no object or container " + thing;
  std::string why;
  return can_hold(location, thing, &why) ? "" : why;
}

bool SymbolicWorld::can_hold(const std::string& loc, const std::string& thing, const Body& b,
                             std::string* why) const {
  // The rule book (world/space_rules.hpp) decides, on this world's counts.
  world::LocationNow at;
  if (is_region(loc) || is_container(loc)) {
    at.kind = is_region(loc) ? world::LocationNow::Kind::Region : world::LocationNow::Kind::Container;
    at.held = at.kind == world::LocationNow::Kind::Container && *placement_.location_of(loc) == kInHand;
    at.usable = usable(loc);
    at.capacity = capacity(loc);
    at.count = count_at(loc, thing);
    at.used = used_at(loc, thing);
  }
  std::string w = world::refusal(thing, b, loc, at, options_.fit);
  if (w.empty()) return true;
  if (why) *why = std::move(w);
  return false;
}

world::Vec3 SymbolicWorld::point_of_location(const std::string& loc) const {
  for (const auto& r : regions_)
    if (r.name == loc) return r.center;
  if (is_container(loc)) return point_of_thing(loc);
  return home_;
}

world::Vec3 SymbolicWorld::point_of_thing(const std::string& thing) const {
  const std::string* loc = placement_.location_of(thing);
  if (!loc) return home_;
  if (*loc == kInHand) return hand_point();
  if (*loc == world::kNoLocation) {
    auto it = loose_.find(thing);
    return it == loose_.end() ? home_ : it->second;
  }
  return point_of_location(*loc);
}

std::string SymbolicWorld::closest_valid(const std::string& thing, const world::Vec3& p,
                                         bool regions_only) const {
  std::string best = world::kNoLocation;
  double best_d = kInf;
  for (const auto& loc : location_names()) {
    if (regions_only && !is_region(loc)) continue;
    if (!can_hold(loc, thing)) continue;
    const double d = distance(point_of_location(loc), p);
    if (d < best_d) best = loc, best_d = d;
  }
  return best;
}

void SymbolicWorld::put(const std::string& thing, const std::string& loc, const world::Vec3& p) {
  placement_.things[thing].location = loc;
  unmoved_.erase(thing);
  if (loc == world::kNoLocation)
    loose_[thing] = p;
  else
    loose_.erase(thing);
  if (!is_container(thing)) return;
  // Geometry knows the containers that stand somewhere (at their region's centre), not the held one.
  geometry_.remove_container(thing);
  if (loc == kInHand) return;
  const ContainerInfo& info = containers_.at(thing);
  world::Container c;
  c.name = thing;
  c.cls = info.cls;
  c.position = loc == world::kNoLocation ? p : point_of_location(loc);
  c.size = info.size;
  c.capacity = info.capacity;
  geometry_.add_container(c);
}

void SymbolicWorld::erase(const std::string& thing) {
  placement_.things.erase(thing);
  loose_.erase(thing);
  unmoved_.erase(thing);
  object_size_.erase(thing);
}

std::string SymbolicWorld::locate(const world::Intervention& iv, bool container) const {
  if (!iv.location.empty()) return iv.location;
  if (iv.position) return container ? geometry_.locate_region(*iv.position) : geometry_.locate(*iv.position);
  return "";
}

// ---------------------------------------------------------------- the move

world::Vec3 SymbolicWorld::hand_point() const {
  if (phase_ == Phase::Approach || phase_ == Phase::Carry || phase_ == Phase::Return) {
    const double span = phase_end_ - phase_start_;
    const double f = span > 0 ? std::clamp((time_ - phase_start_) / span, 0.0, 1.0) : 1.0;
    return lerp(seg_from_, seg_to_, f);
  }
  return hand_point_;
}

std::string SymbolicWorld::held() const {
  if (!holding_phase(phase_)) return "";
  const std::string* loc = placement_.location_of(move_.thing);
  return loc && *loc == kInHand ? move_.thing : "";
}

void SymbolicWorld::begin_phase(Phase p, double duration, const world::Vec3& from, const world::Vec3& to) {
  phase_ = p;
  phase_start_ = time_;
  phase_end_ = time_ + std::max(0.0, duration);
  seg_from_ = from;
  seg_to_ = to;
}

void SymbolicWorld::finish(MoveStatus s, const std::string& why) {
  phase_ = Phase::Idle;
  if (halted_) return;  // poll() already says Failed ("halted")
  status_ = s;
  why_ = why;
}

void SymbolicWorld::start(const Move& m) {
  if (phase_ != Phase::Idle)
    throw std::logic_error("SymbolicWorld::start: a move is running or the arm is busy");
  move_ = m;
  halted_ = false;
  fail_at_.reset();
  status_ = MoveStatus::Running;
  why_.clear();

  // Always two draws per move, so that the stream stays aligned whatever the options.
  const double u = fail_rng_.unit();
  const std::uint64_t k = fail_rng_.below(4);
  static constexpr Phase kFailPhases[] = {Phase::Approach, Phase::Grasp, Phase::Carry, Phase::Place};
  if (options_.fails && options_.fails(m)) {
    fail_at_ = options_.fails_in;
  } else if (u < options_.failure_probability) {
    fail_at_ = kFailPhases[k];
  }

  const std::string* loc = placement_.location_of(m.thing);
  if (!loc) return finish(MoveStatus::Failed, m.thing + " is not in the world");
  if (!m.from.empty() && *loc != m.from)
    return finish(MoveStatus::Failed, m.thing + " is in " + *loc + ", not in " + m.from);
  if (!is_region(m.to) && !is_container(m.to)) return finish(MoveStatus::Failed, "unknown location " + m.to);
  if (m.to == m.thing) return finish(MoveStatus::Failed, m.thing + " cannot go into itself");
  if (is_container(m.thing) && !is_region(m.to))
    return finish(MoveStatus::Failed, m.thing + " is a container: it only goes into a region");

  source_ = *loc;
  source_point_ = point_of_thing(m.thing);
  dest_point_ = point_of_location(m.to);
  const world::Vec3 from = hand_point_;
  begin_phase(Phase::Approach, options_.approach_base + distance(from, source_point_) / options_.speed, from,
              source_point_);
}

void SymbolicWorld::begin_return(const std::string& reason) {
  return_reason_ = reason;
  const std::string& thing = move_.thing;
  const world::Vec3 near =
      is_region(source_) || is_container(source_) ? point_of_location(source_) : source_point_;
  return_to_ = can_hold(source_, thing) ? source_ : closest_valid(thing, near, false);
  const world::Vec3 from = hand_point();
  const world::Vec3 to = return_to_ == world::kNoLocation ? near : point_of_location(return_to_);
  begin_phase(Phase::Return, options_.return_base + distance(from, to) / options_.speed + options_.place,
              from, to);
}

void SymbolicWorld::end_phase() {
  hand_point_ = seg_to_;
  const std::string& thing = move_.thing;
  switch (phase_) {
    case Phase::Idle:
      return;
    case Phase::Approach:
      if (fail_at_ == Phase::Approach) return finish(MoveStatus::Failed, "approach to " + thing + " failed");
      return begin_phase(Phase::Grasp, options_.grasp, seg_to_, seg_to_);
    case Phase::Grasp: {
      const std::string* loc = placement_.location_of(thing);
      if (!loc) return finish(MoveStatus::Failed, thing + " was gone when the gripper closed");
      if (*loc != source_)
        return finish(MoveStatus::Failed,
                      thing + " was no longer in " + source_ + " when the gripper closed");
      if (fail_at_ == Phase::Grasp) return finish(MoveStatus::Failed, "grasp of " + thing + " failed");
      put(thing, kInHand, seg_to_);
      if (is_region(move_.to) || is_container(move_.to)) dest_point_ = point_of_location(move_.to);
      return begin_phase(Phase::Carry, options_.carry_base + distance(seg_to_, dest_point_) / options_.speed,
                         seg_to_, dest_point_);
    }
    case Phase::Carry:
      if (fail_at_ == Phase::Carry) return begin_return("carry of " + thing + " failed");
      return begin_phase(Phase::Place, options_.place, seg_to_, seg_to_);
    case Phase::Place: {
      if (fail_at_ == Phase::Place) return begin_return("place of " + thing + " failed");
      std::string why;
      if (!can_hold(move_.to, thing, &why)) return begin_return("cannot place " + thing + ": " + why);
      put(thing, move_.to, seg_to_);
      hand_ = move_.to;
      return begin_phase(Phase::Retreat, options_.retreat, seg_to_, seg_to_);
    }
    case Phase::Retreat:
      return finish(MoveStatus::Succeeded, "");
    case Phase::Return: {
      std::string to = return_to_;
      if (!can_hold(to, thing)) {
        const world::Vec3 near =
            is_region(source_) || is_container(source_) ? point_of_location(source_) : source_point_;
        to = closest_valid(thing, near, false);
      }
      put(thing, to, seg_to_);
      if (to != world::kNoLocation) hand_ = to;
      return finish(MoveStatus::Failed, return_reason_ + " (" + thing + " put back in " + to + ")");
    }
  }
}

MoveStatus SymbolicWorld::poll(std::string* why) {
  if (status_ == MoveStatus::Failed && why) *why = why_;
  return status_;
}

void SymbolicWorld::halt() {
  if (phase_ == Phase::Idle || halted_) return;
  halted_ = true;
  status_ = MoveStatus::Failed;
  why_ = "halted";
  const world::Vec3 p = hand_point();
  switch (phase_) {
    case Phase::Approach:
    case Phase::Grasp:
      hand_point_ = p;
      return begin_phase(Phase::Retreat, options_.retreat, p, p);
    case Phase::Carry:
    case Phase::Place:
      return begin_return("halted");
    default:
      return;  // Retreat, Return: already making the arm safe
  }
}

void SymbolicWorld::lose_held(const std::string& why) {
  hand_point_ = hand_point();
  phase_ = Phase::Idle;
  if (halted_) return;
  status_ = MoveStatus::Failed;
  why_ = why;
}

// ---------------------------------------------------------------- time

double SymbolicWorld::next_event_time() const { return phase_ != Phase::Idle ? phase_end_ : kInf; }

void SymbolicWorld::advance(double dt) {
  const double target = time_ + std::max(0.0, dt);
  while (phase_ != Phase::Idle && phase_end_ <= target + kTimeSlack) {
    time_ = std::max(time_, phase_end_);
    end_phase();
  }
  time_ = std::max(time_, target);
}

std::vector<WorldEvent> SymbolicWorld::take_events() {
  std::vector<WorldEvent> out;
  out.swap(pending_);
  return out;
}

// ---------------------------------------------------------------- interventions

WorldEvent SymbolicWorld::apply(const world::Intervention& iv) { return apply_now(iv); }

void SymbolicWorld::remove_container_spilling(const std::string& name, std::string* detail) {
  const std::string stood = *placement_.location_of(name);
  const world::Vec3 p = point_of_thing(name);
  std::vector<std::string> contents;
  for (const auto& [n, t] : placement_.things)
    if (t.location == name) contents.push_back(n);
  erase(name);
  containers_.erase(name);
  container_order_.erase(std::find(container_order_.begin(), container_order_.end(), name));
  geometry_.remove_container(name);
  if (hand_ == name) hand_ = is_region(stood) ? stood : "";
  for (const auto& c : contents) {
    if (is_region(stood) && can_hold(stood, c)) {
      put(c, stood, p);
      *detail += "; " + c + " -> " + stood;
    } else {
      const std::string to = closest_valid(c, p, true);
      put(c, to, p);
      *detail += "; " + c + " -> " + to + (is_region(stood) ? " (" + stood + " has no room)" : "");
    }
  }
}

WorldEvent SymbolicWorld::apply_now(world::Intervention iv) {
  WorldEvent ev;
  ev.time = time_;
  auto done = [&](bool applied, std::string detail) {
    ev.what = iv;
    ev.applied = applied;
    ev.detail = std::move(detail);
    pending_.push_back(ev);
    history_.push_back(ev);
    return ev;
  };
  auto fresh = [&](const std::string& n) -> std::string {
    if (n.empty()) return "no name given";
    if (n == kInHand || n == world::kNoLocation) return "'" + n + "' cannot be a name";
    if (placement_.things.count(n) || is_region(n)) return n + " already exists";
    return "";
  };
  const std::string* where = iv.subject.empty() ? nullptr : placement_.location_of(iv.subject);
  if (iv.position)
    if (std::string off = world::off_table(table_, *iv.position); !off.empty()) return done(false, std::move(off));

  switch (iv.kind) {
    case Kind::Relocate: {
      if (!where) return done(false, "no object or container " + (iv.subject.empty() ? "given" : iv.subject));
      const std::string to = locate(iv, is_container(iv.subject));
      if (to.empty()) return done(false, "relocate needs a location or a position");
      const bool held_now = *where == kInHand;
      if (!held_now && *where == to) return done(true, iv.subject + " already in " + to);
      std::string why;
      if (!loose_ok(iv, to) && !can_hold(to, iv.subject, &why)) return done(false, why);
      const world::Vec3 p = iv.position ? *iv.position : point_of_thing(iv.subject);
      put(iv.subject, to, p);
      if (held_now) {
        lose_held("taken from the gripper");
        return done(true, iv.subject + " taken from the gripper to " + to);
      }
      return done(true, iv.subject + " -> " + to);
    }
    case Kind::Add:
    case Kind::AddContainer: {
      const bool cont = iv.kind == Kind::AddContainer;
      if (iv.cls.empty()) iv.cls = cont ? "tray" : "block";
      if (std::string why = fresh(iv.subject); !why.empty()) return done(false, why);
      auto cls = class_is_container_.find(iv.cls);
      if (cls != class_is_container_.end() && cls->second != cont)
        return done(false, "class " + iv.cls + " is a class of " + (cont ? "objects" : "containers"));
      const std::string to = locate(iv, cont);
      if (to.empty())
        return done(false, std::string(cont ? "add_container" : "add") + " needs a location or a position");
      if (cont && !loose_ok(iv, to) && !is_region(to) && is_container(to))
        return done(false, to + " is not a region: containers do not nest");
      std::string why;
      if (!loose_ok(iv, to) && !can_hold(to, iv.subject, new_body(iv.cls, cont), &why))
        return done(false, why);
      const world::Vec3 p = iv.position ? *iv.position : point_of_location(to);
      if (cont) {
        auto tmpl = class_template_.find(iv.cls);
        ContainerInfo info = tmpl != class_template_.end()
                                 ? tmpl->second
                                 : ContainerInfo{iv.cls, options_.added_container_capacity};
        containers_[iv.subject] = info;
        container_order_.push_back(iv.subject);
      } else {
        object_size_[iv.subject] = new_body(iv.cls, false).size;
      }
      class_is_container_[iv.cls] = cont;
      placement_.set(iv.subject, to, iv.cls, cont);
      put(iv.subject, to, p);
      return done(true, iv.subject + " (" + iv.cls + ") added in " + to);
    }
    case Kind::Remove: {
      if (!where || is_container(iv.subject))
        return done(false, (where ? iv.subject + " is a container: use remove_container"
                                  : "no object " + (iv.subject.empty() ? "given" : iv.subject)));
      const bool held_now = *where == kInHand;
      const std::string was = *where;
      erase(iv.subject);
      if (held_now) {
        lose_held("taken from the gripper");
        return done(true, iv.subject + " taken from the gripper and removed");
      }
      return done(true, iv.subject + " removed from " + was);
    }
    case Kind::RemoveContainer: {
      if (!where || !is_container(iv.subject))
        return done(false, where ? iv.subject + " is an object: use remove"
                                 : "no container " + (iv.subject.empty() ? "given" : iv.subject));
      const bool held_now = *where == kInHand;
      std::string detail =
          iv.subject + (held_now ? " taken from the gripper and removed" : " removed from " + *where);
      remove_container_spilling(iv.subject, &detail);
      if (held_now) lose_held("taken from the gripper");
      return done(true, detail);
    }
    case Kind::TakeFromGripper: {
      const std::string h = held();
      if (h.empty()) return done(false, "nothing in the gripper");
      iv.subject = h;
      const std::string to = locate(iv, is_container(h));
      if (to.empty()) {
        std::string detail = h + " taken from the gripper and removed";
        if (is_container(h))
          remove_container_spilling(h, &detail);
        else
          erase(h);
        lose_held("taken from the gripper");
        return done(true, detail);
      }
      std::string why;
      if (!loose_ok(iv, to) && !can_hold(to, h, &why))
        return done(false, why + "; " + h + " stays in the gripper");
      put(h, to, iv.position ? *iv.position : hand_point());
      lose_held("taken from the gripper");
      return done(true, h + " taken from the gripper to " + to);
    }
    case Kind::AddRegion:
      return done(false, "a region cannot be added to a running world (add-region is a change for the planner)");
  }
  return done(false, "unknown intervention");
}

// ---------------------------------------------------------------- invariants

std::string SymbolicWorld::check_invariants() const {
  std::string out;
  auto bad = [&](const std::string& what) { out += what + "\n"; };
  int in_hand = 0;
  for (const auto& [name, t] : placement_.things) {
    if (t.container != is_container(name)) bad(name + ": container flag disagrees with the containers");
    const std::string& l = t.location;
    if (l == kInHand) {
      ++in_hand;
      if (name != move_.thing || !holding_phase(phase_)) bad(name + " is in the hand but no move holds it");
    } else if (l == world::kNoLocation) {
      if (!loose_.count(name)) bad(name + " is at none without a point");
    } else if (is_container(l)) {
      if (t.container) bad(name + " is a container inside container " + l);
      if (l == name) bad(name + " is inside itself");
    } else if (!is_region(l)) {
      bad(name + " is at unknown location " + l);
    }
  }
  if (in_hand > 1) bad(std::to_string(in_hand) + " things in the hand");
  if (holding_phase(phase_) && held().empty())
    bad(std::string("phase ") + to_string(phase_) + " without a held thing");
  for (const auto& [name, p] : loose_) {
    const std::string* l = placement_.location_of(name);
    if (!l || *l != world::kNoLocation) bad(name + " has a loose point but is not at none");
  }
  for (const auto& [name, c] : containers_)
    if (!placement_.things.count(name) || !placement_.things.at(name).container)
      bad("container " + name + " is not in the placement");
  if (container_order_.size() != containers_.size()) bad("container order out of step");
  for (const auto& name : unmoved_)
    if (!placement_.things.count(name)) bad(name + " is listed as unmoved but is not in the world");
  for (const auto& loc : location_names()) {
    const int n = count_at(loc, "");
    if (n > capacity(loc))
      bad(loc + " holds " + std::to_string(n) + " things, capacity " + std::to_string(capacity(loc)));
    // The footprint rules: broken only by things that have stayed where the initial placement put them.
    bool all_unmoved = true;
    for (const auto& [name, t] : placement_.things) {
      if (t.location != loc) continue;
      const bool stayed = unmoved_.count(name) > 0;
      all_unmoved = all_unmoved && stayed;
      if (!stayed && !world::fits(body_of(name).size, usable(loc)))
        bad(name + " was put in " + loc + " where it does not fit");
    }
    const std::int64_t u = used_at(loc, ""), r = world::kRoomUnits;
    if (u > r && !all_unmoved)
      bad(loc + " is over its room (" + std::to_string(u) + " > " + std::to_string(r) +
          " room units) and holds things put there since the start");
  }
  const bool running = status_ == MoveStatus::Running;
  if (running != (phase_ != Phase::Idle && !halted_)) bad("status and phase disagree");
  return out;
}

}  // namespace rtamp::exec
