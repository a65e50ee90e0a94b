#include "rtamp/world/belief.hpp"

#include <algorithm>
#include <cmath>

#include "rtamp/util/error.hpp"

namespace rtamp::world {

const char* to_string(ThingState s) {
  switch (s) {
    case ThingState::Visible: return "visible";
    case ThingState::Occluded: return "occluded";
    case ThingState::Held: return "held";
    case ThingState::OutOfView: return "out-of-view";
    case ThingState::Missing: return "missing";
  }
  return "?";
}

namespace {

// matched_[i] after judge_unseen: the frame found the thing's spot in plain view and empty.
constexpr char kJudgedMissing = 2;

// In the table's plane: things rest on surfaces, and a partly seen thing's height is the least sure.
double distance(const Vec3& a, const Vec3& b) { return std::hypot(a[0] - b[0], a[1] - b[1]); }

bool finite_positive(double x) { return std::isfinite(x) && x > 0; }

// World time is a sum of simulation steps, so frames 0.1 s apart differ by 0.1 plus or minus
// rounding: the belief's clocks compare durations within this tolerance.
constexpr double kTimeTolerance = 1e-6;

// How far from a thing a partly seen view of it may lie: its footprint's diagonal (the box
// fitted to a part is anchored at the part's far edge).
double reach(const BelievedThing& t, double radius) { return std::max(radius, std::hypot(t.size[0], t.size[1])); }

}  // namespace

Belief::Belief(const Scenario& s, BeliefOptions options) : options_(options), geometry_(s) {
  if (!finite_positive(options.match_radius)) throw Error("belief: match_radius must be a positive number of metres");
  if (!std::isfinite(options.remove_after) || options.remove_after < 0)
    throw Error("belief: remove_after must be a number of seconds >= 0");
  if (options.confirm_sightings < 1 || options.confirm_sightings > 1000)
    throw Error("belief: confirm_sightings must be in 1..1000");
  if (!finite_positive(options.candidate_timeout)) throw Error("belief: candidate_timeout must be a positive number of seconds");
  if (!std::isfinite(options.reidentify_within) || options.reidentify_within < 0)
    throw Error("belief: reidentify_within must be a number of seconds >= 0");
  if (!finite_positive(options.first_sight_radius)) throw Error("belief: first_sight_radius must be a positive number of metres");
  if (!std::isfinite(options.hidden_wait) || options.hidden_wait < 0)
    throw Error("belief: hidden_wait must be a number of seconds >= 0");
  if (!finite_positive(options.rest_height)) throw Error("belief: rest_height must be a positive number of metres");
  auto note_class = [&](const std::string& cls, bool container, const Vec3& size) {
    for (const auto& c : classes_)
      if (c.cls == cls) return;
    classes_.push_back({cls, container, size});
  };
  for (const auto& c : s.containers) {
    note_class(c.cls, true, c.size);
    BelievedThing t;
    t.name = c.name, t.cls = c.cls, t.container = true, t.size = c.size, t.base = c.position;
    things_.push_back(std::move(t));
  }
  for (const auto& o : s.objects) {
    note_class(o.cls, false, o.size);
    BelievedThing t;
    t.name = o.name, t.cls = o.cls, t.size = o.size, t.base = o.position;
    things_.push_back(std::move(t));
  }
  // Classes only a person brings, and the default ones, at the default sizes.
  for (const auto& i : s.interventions) {
    if (i.kind == Change::Kind::AddContainer) note_class(i.cls.empty() ? "tray" : i.cls, true, Container{}.size);
    if (i.kind == Change::Kind::Add) note_class(i.cls.empty() ? "block" : i.cls, false, Object{}.size);
  }
  note_class("tray", true, Container{}.size);
  note_class("block", false, Object{}.size);
  locate_all();
}

const BelievedThing* Belief::find(const std::string& name) const {
  for (const auto& t : things_)
    if (t.name == name) return &t;
  return nullptr;
}

void Belief::update(double time, const std::vector<Detection>& seen, const Visibility& visibility,
                    const Gripper& gripper) {
  if (!std::isfinite(time) || time < time_)
    throw Error("belief: frame time " + std::to_string(time) + " s is before the last frame's (" +
                std::to_string(time_) + " s)");
  time_ = time;
  before_.clear();
  for (const auto& t : things_) before_.push_back(t.base);
  follow_gripper(gripper);
  match(time, seen);
  feel_let_go(time);
  feel_failed_grasp(time, gripper);
  judge_unseen(time, visibility);
  promote(time, seen);
  locate_all();
}

void Belief::follow_gripper(const Gripper& g) {
  if (g.holds != held_) {
    for (auto& t : things_) {
      if (!held_.empty() && t.name == held_) {
        t.state = ThingState::Occluded;  // put down where the tool left it
        if (t.base[2] > options_.rest_height) let_go_ = t.name;  // ...unless that is in the air
      }
      if (!g.holds.empty() && t.name == g.holds)
        held_offset_ = {t.base[0] - g.tool[0], t.base[1] - g.tool[1], t.base[2] - g.tool[2]};
    }
    held_ = g.holds;
  }
  for (auto& t : things_)
    if (!held_.empty() && t.name == held_) {
      t.state = ThingState::Held;
      t.base = {g.tool[0] + held_offset_[0], g.tool[1] + held_offset_[1], g.tool[2] + held_offset_[2]};
      t.missing_since = -1;
    }
}

void Belief::match(double time, const std::vector<Detection>& seen) {
  used_.assign(seen.size(), 0);
  matched_.assign(things_.size(), 0);
  whole_.assign(things_.size(), 0);
  // Below the table: a side face taken for a top; no thing's pose.
  for (std::size_t j = 0; j < seen.size(); ++j)
    if (seen[j].base[2] < -kBelowTolerance) used_[j] = 1;
  for (std::size_t i = 0; i < things_.size(); ++i)
    if (things_[i].state == ThingState::Held) {
      matched_[i] = 1;
      for (std::size_t j = 0; j < seen.size(); ++j)
        if (!used_[j] && seen[j].cls == things_[i].cls && distance(seen[j].base, things_[i].base) <= options_.match_radius) {
          used_[j] = 1;
          things_[i].last_seen = time;
        }
    }
  // Containers first: their contents move with them before the objects are matched.
  // A detection in the air matches only a thing believed in the air (carried in a held
  // container), one at rest only a thing at rest.
  const auto in_air = [&](const Vec3& base) { return base[2] > options_.rest_height; };
  for (const bool containers : {true, false}) {
    if (!containers) carry_contents(before_);
    pairs_.clear();
    for (std::size_t i = 0; i < things_.size(); ++i) {
      if (matched_[i] || things_[i].container != containers) continue;
      for (std::size_t j = 0; j < seen.size(); ++j) {
        if (used_[j] || seen[j].cls != things_[i].cls || in_air(seen[j].base) != in_air(things_[i].base)) continue;
        const double d = distance(seen[j].base, things_[i].base);
        const double gate = things_[i].last_seen < 0 ? options_.first_sight_radius
                            : seen[j].complete       ? options_.match_radius
                                                     : reach(things_[i], options_.match_radius);
        if (d <= gate) pairs_.push_back({d, {i, j}});
      }
    }
    std::sort(pairs_.begin(), pairs_.end());
    for (const auto& [d, ij] : pairs_) {
      const auto [i, j] = ij;
      if (matched_[i] || used_[j]) continue;
      matched_[i] = used_[j] = 1;
      whole_[i] = seen[j].complete;
      BelievedThing& t = things_[i];
      t.state = ThingState::Visible;
      t.last_seen = time;
      t.missing_since = -1;
      if (seen[j].complete || t.doubted || t.provisional) {
        t.base = seen[j].base, t.yaw = seen[j].yaw, t.doubted = false;
        t.provisional = t.provisional && !seen[j].complete;
      }
    }
  }
  // Whatever else is in the air is in the gripper: never a new thing.
  for (std::size_t j = 0; j < seen.size(); ++j)
    if (in_air(seen[j].base)) used_[j] = 1;
}

void Belief::carry_contents(const std::vector<Vec3>& before) {
  for (std::size_t c = 0; c < things_.size(); ++c) {
    const BelievedThing& box = things_[c];
    if (!box.container) continue;
    const Vec3 d{box.base[0] - before[c][0], box.base[1] - before[c][1], box.base[2] - before[c][2]};
    if (d[0] == 0 && d[1] == 0 && d[2] == 0) continue;
    for (std::size_t i = 0; i < things_.size(); ++i) {
      BelievedThing& t = things_[i];
      if (t.container || matched_[i] || t.on != box.name) continue;
      for (int k = 0; k < 3; ++k) t.base[static_cast<std::size_t>(k)] += d[static_cast<std::size_t>(k)];
    }
  }
}

void Belief::feel_failed_grasp(double time, const Gripper& g) {
  if (g.failed_grasp_at < 0 || g.failed_grasp_at <= failed_grasp_at_) return;
  failed_grasp_at_ = g.failed_grasp_at;
  // The grasp was for the thing whose box holds the tool point, a block before a container
  // (a block on a tray, not the tray), the nearest before the others.
  constexpr double kSlack = 0.005;  // m around the believed box
  std::size_t target = things_.size();
  double nearest = INFINITY;
  for (std::size_t i = 0; i < things_.size(); ++i) {
    const BelievedThing& t = things_[i];
    if (matched_[i] || t.name == held_) continue;
    const double dx = g.failed_grasp_tool[0] - t.base[0], dy = g.failed_grasp_tool[1] - t.base[1];
    const double c = std::cos(t.yaw), s = std::sin(t.yaw);
    const double along = c * dx + s * dy, across = -s * dx + c * dy;
    const double up = g.failed_grasp_tool[2] - t.base[2];
    if (std::abs(along) > t.size[0] / 2 + kSlack || std::abs(across) > t.size[1] / 2 + kSlack ||
        up < -kSlack || up > t.size[2] + kSlack)
      continue;
    const double rank = std::hypot(dx, dy) + (t.container ? 1e3 : 0);  // m; containers last
    if (rank >= nearest) continue;
    nearest = rank;
    target = i;
  }
  if (target == things_.size()) return;
  BelievedThing& t = things_[target];
  if (!g.failed_grasp_empty) {
    t.doubted = true;
    return;
  }
  t.state = ThingState::Missing;
  t.missing_since = time - options_.remove_after;
  matched_[target] = kJudgedMissing;
}

void Belief::feel_let_go(double time) {
  if (let_go_.empty()) return;
  // Nothing rests in the air: the thing (and what it carried) is not where the hand let it
  // go, unless this frame sees it there. Seen elsewhere soon, it is re-identified.
  for (std::size_t i = 0; i < things_.size(); ++i) {
    BelievedThing& t = things_[i];
    if (matched_[i] || t.base[2] <= options_.rest_height || (t.name != let_go_ && t.on != let_go_)) continue;
    t.state = ThingState::Missing;
    t.missing_since = time - options_.remove_after;
    matched_[i] = kJudgedMissing;
  }
  let_go_.clear();
}

void Belief::judge_unseen(double time, const Visibility& visibility) {
  for (std::size_t i = 0; i < things_.size(); ++i) {
    if (matched_[i]) continue;
    BelievedThing& t = things_[i];
    switch (visibility.sight(t)) {
      case Sight::OutOfView:
        t.state = ThingState::OutOfView;
        t.missing_since = -1;
        break;
      case Sight::Occluded:
        t.state = ThingState::Occluded;
        t.missing_since = -1;
        break;
      case Sight::Elsewhere:
        break;  // another camera's to judge
      case Sight::Visible:
        if (t.state != ThingState::Missing) t.state = ThingState::Missing, t.missing_since = time;
        matched_[i] = kJudgedMissing;
        break;
    }
  }
  // Missing long enough, and judged so by this frame: believed removed (a container's
  // contents stay where they are).
  std::size_t k = 0;
  for (std::size_t i = 0; i < things_.size(); ++i) {
    const BelievedThing& t = things_[i];
    if (matched_[i] == kJudgedMissing && time - t.missing_since >= options_.remove_after - kTimeTolerance) {
      if (t.container) geometry_.remove_container(t.name);
      removed_.push_back({t, time});
      continue;
    }
    if (k != i) things_[k] = std::move(things_[i]), matched_[k] = matched_[i], whole_[k] = whole_[i];
    ++k;
  }
  things_.resize(k);
  matched_.resize(k);
  whole_.resize(k);
  std::erase_if(removed_, [&](const Removed& r) { return time - r.time > options_.reidentify_within + kTimeTolerance; });
}

void Belief::promote(double time, const std::vector<Detection>& seen) {
  std::erase_if(candidates_, [&](const Candidate& c) { return time - c.last_seen > options_.candidate_timeout + kTimeTolerance; });
  for (std::size_t j = 0; j < seen.size(); ++j) {
    if (used_[j]) continue;
    const Detection& d = seen[j];
    // A second view of a thing already explained (a blob the arm cut in two) is no
    // candidate — but a complete view beside a thing this frame saw whole is another thing
    // (a look-alike pushed against it), whatever the distance.
    bool known = false;
    for (std::size_t i = 0; i < things_.size(); ++i) {
      const BelievedThing& t = things_[i];
      if (d.complete && i < whole_.size() && whole_[i]) continue;
      known = known || (t.cls == d.cls && distance(t.base, d.base) <= (d.complete ? options_.match_radius
                                                                                  : reach(t, options_.match_radius)));
    }
    if (known) continue;
    Candidate* nearest = nullptr;
    for (auto& c : candidates_)
      if (c.seen.cls == d.cls && distance(c.seen.base, d.base) <= options_.match_radius &&
          (!nearest || distance(c.seen.base, d.base) < distance(nearest->seen.base, d.base)))
        nearest = &c;
    if (!nearest) {
      candidates_.push_back({d, 0, time, time});
      nearest = &candidates_.back();
    } else if (nearest->last_seen == time) {
      continue;  // two detections of one candidate in a frame count once
    }
    if (d.complete || !nearest->seen.complete) nearest->seen = d;  // the last complete pose, if any
    ++nearest->sightings;
    nearest->last_seen = time;
  }
  // Confirmed candidates, containers first (the things a moved container carries go with it).
  for (const bool containers : {true, false})
    for (std::size_t k = 0; k < candidates_.size();) {
      const Candidate c = candidates_[k];
      const ClassInfo* info = nullptr;
      for (const auto& ci : classes_)
        if (ci.cls == c.seen.cls) info = &ci;
      const bool container = info && info->container;
      if (container != containers || c.sightings < options_.confirm_sightings) {
        ++k;
        continue;
      }
      candidates_.erase(candidates_.begin() + static_cast<std::ptrdiff_t>(k));
      bool known = false;  // explained meanwhile (carried with its container), by a thing not seen whole beside it
      for (std::size_t i = 0; i < things_.size(); ++i)
        known = known || (!(c.seen.complete && i < whole_.size() && whole_[i]) && things_[i].cls == c.seen.cls &&
                          distance(things_[i].base, c.seen.base) <= options_.match_radius);
      if (known) continue;
      // A Missing thing of the class moved here (the nearest); or one removed a moment ago;
      // or, once no hidden thing of the class may be it, a new thing.
      BelievedThing* moved = nullptr;
      for (auto& t : things_)
        if (t.cls == c.seen.cls && t.state == ThingState::Missing &&
            (!moved || distance(t.base, c.seen.base) < distance(moved->base, c.seen.base)))
          moved = &t;
      if (!moved) {  // removed a moment ago: it was moved where the camera could not see it
        const Removed* last = nullptr;
        for (const auto& r : removed_)
          if (r.thing.cls == c.seen.cls && (!last || r.time >= last->time)) last = &r;
        if (last) {
          things_.push_back(last->thing);
          removed_.erase(removed_.begin() + (last - removed_.data()));
          moved = &things_.back();
          if (container) geometry_.add_container({moved->name, moved->cls, c.seen.base, moved->size, 4, {}});
        }
      }
      // Not yet new while a thing of its class is hidden: that one may have moved here.
      if (!moved && time - c.first_seen < options_.hidden_wait - kTimeTolerance) {
        bool hidden = false;
        for (const auto& t : things_) hidden = hidden || (t.cls == c.seen.cls && t.state == ThingState::Occluded);
        if (hidden) {
          candidates_.insert(candidates_.begin() + static_cast<std::ptrdiff_t>(k), c);
          ++k;
          continue;
        }
      }
      if (!moved) {
        BelievedThing t;
        t.name = fresh_name(c.seen.cls);
        t.cls = c.seen.cls;
        t.container = container;
        t.size = info ? info->size : Object{}.size;
        t.base = c.seen.base;
        things_.push_back(std::move(t));
        moved = &things_.back();
        if (container) geometry_.add_container({moved->name, moved->cls, c.seen.base, moved->size, 4, {}});
      }
      if (container) {
        const Vec3 d{c.seen.base[0] - moved->base[0], c.seen.base[1] - moved->base[1], c.seen.base[2] - moved->base[2]};
        for (auto& t : things_)
          if (!t.container && t.on == moved->name && t.state != ThingState::Held) {
            for (std::size_t a = 0; a < 3; ++a) t.base[a] += d[a];
            t.state = ThingState::Occluded;  // until it is seen where its container took it
            t.missing_since = -1;
          }
      }
      moved->base = c.seen.base;
      moved->yaw = c.seen.yaw;
      moved->provisional = !c.seen.complete;
      moved->state = ThingState::Visible;
      moved->last_seen = time;
      moved->missing_since = -1;
    }
}

bool Belief::confirming() const {
  if (!candidates_.empty()) return true;
  for (const auto& t : things_)
    if (t.state == ThingState::Missing) return true;
  return false;
}

std::string Belief::fresh_name(const std::string& cls) {
  for (;;) {
    std::string name = cls + "_seen" + std::to_string(++added_);
    if (!find(name)) return name;
  }
}

void Belief::locate_all() {
  for (const auto& t : things_)
    if (t.container) geometry_.move_container(t.name, t.base);
  for (auto& t : things_) {
    t.on.clear();
    if (t.container || t.state == ThingState::Held) continue;
    std::string at = geometry_.locate(t.base);
    for (const auto& c : things_)
      if (c.container && c.name == at) t.on = std::move(at);
  }
}

Placement Belief::placement() const {
  Placement p;
  for (const auto& t : things_) {
    if (t.state == ThingState::Held)
      p.set(t.name, "hand", t.cls, t.container);
    else
      p.set(t.name, t.container ? geometry_.locate_region(t.base) : geometry_.locate(t.base), t.cls, t.container);
  }
  return p;
}

}  // namespace rtamp::world
