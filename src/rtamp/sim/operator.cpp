#include "rtamp/sim/operator.hpp"

#include "rtamp/sim/scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "rtamp/util/error.hpp"
#include "rtamp/util/format.hpp"
#include "rtamp/world/table.hpp"

namespace rtamp::sim {

namespace {

using Kind = world::Intervention::Kind;

Eigen::Isometry3d at(const world::Vec3& p) {
  Eigen::Isometry3d t = Eigen::Isometry3d::Identity();
  t.translation() = Eigen::Vector3d(p[0], p[1], p[2]);
  return t;
}

double yaw_of(const Eigen::Isometry3d& p) { return std::atan2(p.linear()(1, 0), p.linear()(0, 0)); }

std::string fmt(const world::Vec3& p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.3f, %.3f, %.3f)", p[0], p[1], p[2]);
  return buf;
}

}  // namespace

Operator::Operator(Simulation& sim) : sim_(sim) {}

world::Geometry Operator::current_geometry() const { return sim::current_geometry(sim_); }

std::vector<int> Operator::contents_of(int container) const { return sim::contents_of(sim_, container); }

std::optional<world::Vec3> Operator::spot_in(const std::string& location, const world::Body& body,
                                             const std::vector<int>& exclude) {
  // Keep clear of the gripper's fingers when the hand is low over the table.
  std::vector<world::Footprint> keep_clear;
  const Eigen::Vector3d tool = sim_.tool_pose().translation();
  if (tool.z() < 0.25) keep_clear.push_back(world::footprint_at({tool.x(), tool.y(), 0}, {0.1, 0.12, 0}));
  return sim::free_spot(sim_, location, body, exclude, world::kPlaceGap, keep_clear);
}

std::string Operator::set_down(const std::vector<int>& things, const Eigen::Vector3d& where) {
  if (things.empty()) return "";
  // Nearest region first (the one under `where`, if any, is at distance 0).
  std::vector<std::pair<double, std::string>> regions;
  const world::Geometry g = current_geometry();
  const std::string under = g.locate_region({where.x(), where.y(), 0});
  for (const auto& r : sim_.scenario().regions)
    regions.emplace_back(r.name == under ? 0.0 : std::hypot(r.center[0] - where.x(), r.center[1] - where.y()), r.name);
  std::stable_sort(regions.begin(), regions.end());
  std::string out;
  for (std::size_t n = 0; n < things.size(); ++n) {
    const int k = things[n];
    const Thing& t = sim_.thing(k);
    // Things still to be set down are in the air, not in anyone's way.
    const std::vector<int> exclude(things.begin() + static_cast<std::ptrdiff_t>(n), things.end());
    std::optional<world::Vec3> to;
    std::string loc;
    for (const auto& [d, name] : regions)
      if (space_refusal(sim_, t.name, {t.size, t.container}, name, exclude).empty() &&
          (to = spot_in(name, {t.size, t.container}, exclude))) {
        loc = name;
        break;
      }
    if (!to) {
      sim_.hide(k);
      out += "; '" + t.name + "' too (no region with room and a free spot)";
      continue;
    }
    sim_.set_pose(k, at({(*to)[0], (*to)[1], (*to)[2] + t.size[2] / 2 + 0.001}));
    out += "; '" + t.name + "' set down in " + loc + " at " + fmt(*to);
  }
  return out;
}

bool Operator::overlaps_anything(const world::Vec3& base, const world::Vec3& size,
                                 const std::vector<int>& exclude) const {
  world::Footprint f = world::footprint_at(base, size);
  for (std::size_t i = 0; i < sim_.things().size(); ++i) {
    const Thing& t = sim_.things()[i];
    const int ii = static_cast<int>(i);
    if (!t.present || t.name.empty() || sim_.held() == ii) continue;
    if (std::find(exclude.begin(), exclude.end(), ii) != exclude.end()) continue;
    const Eigen::Vector3d p = sim_.position(ii);
    // Objects resting inside a container may share its footprint when placed into it.
    if (t.container && base[2] > p.z() + 1e-3) continue;
    if (f.overlaps(world::footprint_at({p.x(), p.y(), 0}, t.size))) return true;
  }
  return false;
}

std::string Operator::first_location(const std::string& thing, const world::Body& body,
                                     const std::vector<int>& exclude, const std::string& avoid) {
  std::vector<std::string> all;
  for (const auto& r : sim_.scenario().regions)
    if (r.name != avoid) all.push_back(r.name);
  for (const auto& t : sim_.things())
    if (t.container && t.present && !t.name.empty() && t.name != avoid) all.push_back(t.name);
  for (const auto& loc : all)
    if (space_refusal(sim_, thing, body, loc, exclude).empty()) return loc;
  return all.empty() ? std::string{} : all.front();
}

OperatorEvent Operator::apply(const world::Intervention& iv) {
  OperatorEvent ev;
  ev.time = sim_.time();
  ev.what = iv;
  auto refuse = [&](std::string why) {
    ev.applied = false;
    ev.detail = std::move(why);
    history_.push_back(ev);
    return ev;
  };
  auto done = [&](std::string what) {
    ev.applied = true;
    ev.detail = std::move(what);
    history_.push_back(ev);
    return ev;
  };
  // Where a thing goes: its explicit position (refused if it overlaps something) or a
  // free spot of its location (the first one with room when none is given). The
  // location, named or where the position falls, must take it by the rule book
  // (world/space_rules.hpp): `why` says which rule refuses it.
  auto target = [&](const std::string& name, const world::Body& body, const std::vector<int>& exclude,
                    const std::string& avoid, std::string& why) -> std::optional<world::Vec3> {
    std::string loc = iv.location;
    if (loc.empty() && iv.position) {
      const world::Geometry g = current_geometry();
      loc = body.container ? g.locate_region(*iv.position) : g.locate(*iv.position);
      if (loc == world::kNoLocation) loc.clear();  // the bare table: no location's rules apply
    } else if (loc.empty()) {
      loc = first_location(name, body, exclude, avoid);
    }
    if (!loc.empty())
      if (std::string w = space_refusal(sim_, name, body, loc, exclude); !w.empty()) {
        why = std::move(w);
        return std::nullopt;
      }
    if (iv.position) {
      if (!overlaps_anything(*iv.position, body.size, exclude)) return *iv.position;
      why = "no free spot for '" + name + "' at " + fmt(*iv.position);
      return std::nullopt;
    }
    auto spot = spot_in(loc, body, exclude);
    if (!spot) why = "no free spot for '" + name + "'";
    return spot;
  };

  if (iv.position)
    if (std::string off = world::off_table(world::table_top(sim_.scenario()), *iv.position); !off.empty())
      return refuse(std::move(off));

  switch (iv.kind) {
    case Kind::Relocate: {
      const int i = sim_.find(iv.subject);
      if (i < 0 || !sim_.thing(i).present) return refuse("no '" + iv.subject + "' in the scene");
      const Thing& t = sim_.thing(i);
      std::vector<int> moved{i};
      if (t.container) {
        auto in = contents_of(i);
        moved.insert(moved.end(), in.begin(), in.end());
      }
      world::Geometry g = current_geometry();
      const Eigen::Vector3d p0 = sim_.position(i);
      std::string here = t.container ? g.locate_region({p0.x(), p0.y(), p0.z()})
                                     : g.locate({p0.x(), p0.y(), p0.z() - t.size[2] / 2});
      std::string why;
      auto to = target(t.name, {t.size, t.container}, moved, here, why);
      if (!to) return refuse(why);
      if (sim_.held() == i) sim_.detach();
      const double z = t.container ? (*to)[2] : (*to)[2] + t.size[2] / 2 + 0.001;
      const Eigen::Vector3d delta = Eigen::Vector3d((*to)[0], (*to)[1], z) - p0;
      for (int k : moved) {
        auto p = sim_.pose(k);
        if (k == i) p = at({(*to)[0], (*to)[1], z});
        else p.translation() += delta;
        sim_.set_pose(k, p);
      }
      return done("to " + fmt(*to));
    }
    case Kind::Add:
    case Kind::AddContainer: {
      const bool container = iv.kind == Kind::AddContainer;
      if (iv.subject.empty()) return refuse("no name for the added thing");
      int existing = sim_.find(iv.subject);
      if (existing >= 0 && sim_.thing(existing).present) return refuse("'" + iv.subject + "' is already there");
      world::Vec3 size = container ? sim_.options().mjcf.spare_tray_size : sim_.options().mjcf.spare_block_size;
      if (existing >= 0) size = sim_.thing(existing).size;
      std::string why;
      auto to = target(iv.subject, {size, container}, {}, "", why);
      if (!to) return refuse(why);
      const double z = container ? (*to)[2] : (*to)[2] + size[2] / 2 + 0.001;
      try {
        sim_.add(iv.subject, iv.cls.empty() ? (container ? "tray" : "block") : iv.cls, container,
                 at({(*to)[0], (*to)[1], z}), size);
      } catch (const Error& e) {
        return refuse(e.message());
      }
      return done("at " + fmt(*to));
    }
    case Kind::Remove:
    case Kind::RemoveContainer: {
      const int i = sim_.find(iv.subject);
      if (i < 0 || !sim_.thing(i).present) return refuse("no '" + iv.subject + "' in the scene");
      // A tray on the table leaves its contents where it stood (they drop onto the
      // region); one in the gripper leaves them in the air, so the person sets them down.
      const bool in_air = sim_.held() == i && sim_.thing(i).container;
      const std::vector<int> in = in_air ? contents_of(i) : std::vector<int>{};
      const Eigen::Vector3d where = sim_.position(i);
      sim_.hide(i);
      return done("removed" + set_down(in, where));
    }
    case Kind::TakeFromGripper: {
      const int i = sim_.held();
      if (i < 0) return refuse("the gripper holds nothing");
      ev.what.subject = sim_.thing(i).name;
      const std::vector<int> in = sim_.thing(i).container ? contents_of(i) : std::vector<int>{};
      const Eigen::Isometry3d from = sim_.pose(i);
      const Thing& t = sim_.thing(i);
      // A destination with no room is refused before anything happens: the thing
      // stays in the gripper (as in the symbolic world), never silently deleted.
      std::optional<world::Vec3> to;
      const bool has_destination = !iv.location.empty() || iv.position.has_value();
      if (has_destination) {
        std::vector<int> moved{i};
        moved.insert(moved.end(), in.begin(), in.end());
        std::string why;
        to = target(t.name, {t.size, t.container}, moved, "", why);
        if (!to) return refuse(why + "; " + t.name + " stays in the gripper");
      }
      sim_.detach();
      if (!to) {
        sim_.hide(i);
        return done("took '" + t.name + "' away" + set_down(in, from.translation()));
      }
      // The thing goes down upright, keeping its yaw; a tray's contents ride along.
      const double z = t.container ? (*to)[2] : (*to)[2] + t.size[2] / 2 + 0.001;
      Eigen::Isometry3d p = at({(*to)[0], (*to)[1], z});
      p.linear() = Eigen::AngleAxisd(yaw_of(from), Eigen::Vector3d::UnitZ()).toRotationMatrix();
      sim_.set_pose(i, p);
      const Eigen::Vector3d delta = p.translation() - from.translation();
      for (int k : in) {
        Eigen::Isometry3d pk = sim_.pose(k);
        pk.translation() += delta + Eigen::Vector3d(0, 0, 0.002);
        sim_.set_pose(k, pk);
      }
      return done("took '" + t.name + "' to " + fmt(*to));
    }
    case Kind::AddRegion:
      return refuse("a region cannot be added to the simulated workspace (add-region is a change for the planner)");
  }
  return refuse("unknown intervention");
}

}  // namespace rtamp::sim
