#include "rtamp/episode/sim_world.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include "rtamp/sim/camera_perception.hpp"

namespace rtamp::episode {

SimWorld::SimWorld(const world::Scenario& scenario, sim::SessionOptions options)
    : session_(scenario, std::move(options)) {}

void SimWorld::advance(double dt) {
  auto& sim = session_.sim();
  const int steps = std::max(1, static_cast<int>(std::lround(dt / sim.timestep())));
  Eigen::Vector3d last = sim.tool_pose().translation();
  for (int k = 0; k < steps; ++k) {
    park_if_idle();
    session_.controller().update();
    sim.step();
    session_.perception().advance();
    const Eigen::Vector3d tool = sim.tool_pose().translation();
    travelled_ += (tool - last).norm();  // the tool path actually travelled
    last = tool;
    if (parking_ && session_.controller().status() != sim::Status::Running) {
      parking_ = false;
      if (session_.controller().status() == sim::Status::Success) hand_.clear();  // home
    }
  }
}

void SimWorld::park_if_idle() {
  if (parking_ || park_refused_ || returning_ || !session_.perception().camera()) return;
  if ((phase_ != Phase::Idle && phase_ != Phase::Done) || session_.sim().held() >= 0) return;
  if (session_.sim().time() - idle_since_ < kParkAfter - 1e-9) return;
  auto& controller = session_.controller();
  if (controller.status() == sim::Status::Running) return;
  if (!session_.skills().start_park()) {
    park_refused_ = true;
    return;
  }
  parking_ = controller.status() == sim::Status::Running;
  park_refused_ = !parking_;  // home already
}

void SimWorld::note(const sim::OperatorEvent& e) {
  events_.push_back(exec::WorldEvent{e.time, e.what, e.applied, e.detail});
  // A person took the thing the arm carries (out of the gripper, or away).
  using K = world::Intervention::Kind;
  const bool carried = phase_ == Phase::Placing || phase_ == Phase::Recovering;
  if (e.applied && carried &&
      (e.what.kind == K::TakeFromGripper ||
       ((e.what.kind == K::Relocate || e.what.kind == K::Remove || e.what.kind == K::RemoveContainer) &&
        e.what.subject == move_.thing)))
    taken_ = true;
}

exec::WorldEvent SimWorld::apply(const world::Intervention& iv) {
  const sim::OperatorEvent e = session_.op().apply(iv);
  note(e);
  return events_.back();
}

std::vector<exec::WorldEvent> SimWorld::take_events() {
  std::vector<exec::WorldEvent> out;
  out.swap(events_);
  return out;
}

world::Placement SimWorld::observe() {
  session_.perception().observe(percept_);
  return percept_.placement();
}

bool SimWorld::holds(const std::string& thing) const {
  const auto& sim = session_.sim();
  return sim.held() >= 0 && sim.held() == sim.find(thing);
}

void SimWorld::end(exec::MoveStatus s, const std::string& why) {
  status_ = s;
  why_ = why;
  phase_ = Phase::Done;
  idle_since_ = session_.sim().time();
  park_refused_ = false;
}

std::string SimWorld::body_of(const std::string& believed) const {
  const sim::CameraPerception* eyes = session_.perception().camera();
  const sim::Simulation& sim = session_.sim();
  if (!eyes || sim.scenario().find_region(believed)) return believed;
  // Not the body of that name: blocks of one colour look alike, and a belief that lost
  // sight of two of them (let go of in the air together, say) may have swapped their names.
  const world::BelievedThing* b = eyes->belief().find(believed);
  if (!b) return believed;
  std::string body = believed;
  double best = 0.1;  // m: farther, nothing is where the thing is believed
  for (int i = 0; i < static_cast<int>(sim.things().size()); ++i) {
    const sim::Thing& t = sim.thing(i);
    if (!t.present || t.name.empty() || t.cls != b->cls) continue;
    const Eigen::Vector3d p = sim.position(i);
    const double d = std::hypot(p.x() - b->base[0], p.y() - b->base[1]);
    if (d < best) best = d, body = t.name;
  }
  return body;
}

void SimWorld::start(const exec::Move& m) {
  if (parking_) {  // the move takes over from where the arm is
    session_.controller().halt();
    parking_ = false;
  }
  move_ = m;
  move_.thing = body_of(m.thing);
  move_.from = body_of(m.from);
  move_.to = body_of(m.to);
  to_ = m.to;
  taken_ = false;
  put_backs_ = 0;
  status_ = exec::MoveStatus::Running;
  why_.clear();
  phase_ = Phase::Picking;
  // With a camera the arm goes where the thing is seen.
  std::optional<sim::SeenThing> seen;
  if (const sim::CameraPerception* eyes = session_.perception().camera())
    if (const world::BelievedThing* b = eyes->belief().find(m.thing)) {
      seen.emplace();
      seen->pose.position = Eigen::Vector3d(b->base[0], b->base[1], b->base[2]);
      seen->pose.yaw = b->yaw;
      seen->size = b->size;
      seen->container = b->container;
    }
  // The point of the location the thing is picked from (its region's centre, its container),
  // from which a failed move's put-back looks for the closest location with room.
  const sim::Simulation& sim = session_.sim();
  const int body = sim.find(move_.thing), from = sim.find(move_.from);
  if (const world::Region* r = sim.scenario().find_region(move_.from))
    source_point_ = Eigen::Vector3d(r->center[0], r->center[1], r->center[2]);
  else if (from >= 0 && sim.thing(from).present)
    source_point_ = sim.position(from);
  else if (body >= 0 && sim.thing(body).present)
    source_point_ = sim.position(body);
  else
    source_point_ = sim.tool_pose().translation();
  if (!session_.skills().start_pick(move_.thing, seen)) end(exec::MoveStatus::Failed, session_.controller().reason());
}

bool SimWorld::place_somewhere(const std::string& preferred) {
  auto& sim = session_.sim();
  const int held = sim.held();
  if (held < 0) return false;
  std::vector<std::string> candidates;
  if (!preferred.empty()) candidates.push_back(preferred);
  // Then, as the symbolic world puts a thing back, every location by the distance of its
  // point from the point of the location the thing was picked from (regions first on
  // ties, then declaration order; into a container only an object).
  std::vector<std::pair<double, std::string>> others;
  auto add = [&](double x, double y, const std::string& name) {
    others.emplace_back(std::hypot(x - source_point_.x(), y - source_point_.y()), name);
  };
  for (const auto& r : sim.scenario().regions) add(r.center[0], r.center[1], r.name);
  if (!sim.thing(held).container)
    for (int i = 0; i < static_cast<int>(sim.things().size()); ++i)
      if (const sim::Thing& t = sim.thing(i); t.container && t.present && !t.name.empty() && i != held)
        add(sim.position(i).x(), sim.position(i).y(), t.name);
  std::stable_sort(others.begin(), others.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (const auto& [d, name] : others) candidates.push_back(name);
  for (const std::string& loc : candidates) {
    if (loc == move_.thing) continue;
    if (!session_.skills().place_spot(held, loc)) continue;
    if (session_.skills().start_place(loc)) {
      placed_at_ = loc;
      return true;
    }
  }
  return false;
}

// A failed move must not leave its thing in the gripper: put it somewhere valid first. A
// failed pick backs the empty gripper off (out of the camera's way).
// A put-back that fails too (its release refused: a person filled that location as well)
// tries the next closest location with room, up to kMaxPutBacks in all, then lets go where it is.
void SimWorld::fail_or_recover(const std::string& why) {
  if (phase_ != Phase::Recovering) failure_ = why;
  if (holds(move_.thing)) {
    const bool first = phase_ != Phase::Recovering;
    phase_ = Phase::Recovering;
    if (put_backs_ < kMaxPutBacks) {
      ++put_backs_;
      if (place_somewhere(first ? move_.from : std::string())) return;
    }
    session_.sim().detach();
  }
  if (phase_ == Phase::Picking && session_.sim().held() < 0 && session_.skills().start_retreat() &&
      session_.controller().status() == sim::Status::Running)
    returning_ = true;
  end(exec::MoveStatus::Failed, failure_);  // `why` may be the controller's reason, which the retreat cleared
}

exec::MoveStatus SimWorld::poll(std::string* why) {
  if (phase_ == Phase::Picking || phase_ == Phase::Placing || phase_ == Phase::Recovering) {
    auto& controller = session_.controller();
    // Taken out of the gripper by a person while it was carried.
    if (taken_) {
      taken_ = false;
      controller.halt();
      if (session_.skills().start_retreat() && controller.status() == sim::Status::Running) returning_ = true;
      end(exec::MoveStatus::Failed, phase_ == Phase::Recovering ? failure_ : "taken from the gripper");
    } else if (controller.status() == sim::Status::Failure) {
      fail_or_recover(controller.reason());
    } else if (controller.status() != sim::Status::Running) {
      switch (phase_) {
        case Phase::Picking: {
          const bool destination = session_.sim().scenario().find_region(move_.to) != nullptr ||
                                   session_.sim().find(move_.to) >= 0;
          phase_ = Phase::Placing;
          if (!destination || !session_.skills().start_place(move_.to))
            fail_or_recover(destination ? controller.reason() : "'" + move_.to + "' is gone");
          break;
        }
        case Phase::Placing:
          hand_ = to_;
          end(exec::MoveStatus::Succeeded, {});
          break;
        case Phase::Recovering:
          hand_ = placed_at_;
          end(exec::MoveStatus::Failed, failure_);
          break;
        default: break;
      }
    }
  }
  if (why && status_ == exec::MoveStatus::Failed) *why = why_;
  return status_;
}

void SimWorld::halt() {
  if (phase_ == Phase::Idle || phase_ == Phase::Done) return;
  auto& controller = session_.controller();
  controller.halt();
  back_thing_ = move_.thing;
  if (holds(move_.thing)) {
    if (place_somewhere(move_.from)) {
      returning_ = true;
      hand_ = placed_at_;
    } else {
      session_.sim().detach();
    }
  } else if (session_.skills().start_retreat() && controller.status() == sim::Status::Running) {
    returning_ = true;
  }
  end(exec::MoveStatus::Failed, "halted");
}

bool SimWorld::busy() {
  auto& controller = session_.controller();
  if (returning_ && controller.status() != sim::Status::Running) {
    returning_ = false;
    if (controller.status() == sim::Status::Failure && holds(back_thing_)) {
      // The put-back after a halt failed (its release refused, say): the closest location with room.
      if (put_backs_ < kMaxPutBacks && (++put_backs_, place_somewhere({}))) {
        returning_ = true;
        hand_ = placed_at_;
      } else {
        session_.sim().detach();
      }
    }
  }
  return returning_;
}

exec::Frame SimWorld::frame(const world::Placement& perceived) {
  const sim::Simulation& sim = session_.sim();
  exec::Frame f;
  f.t = sim.time();
  const robot::Joints q = sim.arm_q();
  f.q = std::array<double, 6>{q[0], q[1], q[2], q[3], q[4], q[5]};
  const Eigen::Vector3d tool = sim.tool_pose().translation();
  f.tool = {tool.x(), tool.y(), tool.z()};
  if (sim.held() >= 0) f.held = sim.thing(sim.held()).name;
  for (int i = 0; i < static_cast<int>(sim.things().size()); ++i) {
    const sim::Thing& t = sim.thing(i);
    if (!t.present || t.name.empty()) continue;
    exec::Frame::Thing ft;
    ft.name = t.name;
    ft.cls = t.cls;
    ft.container = t.container;
    ft.size = t.size;
    const Eigen::Isometry3d pose = sim.pose(i);
    // Blocks' bodies are centred; trays' bodies start at their base.
    const Eigen::Vector3d base =
        t.container ? pose.translation() : Eigen::Vector3d(pose * Eigen::Vector3d(0, 0, -t.size[2] / 2));
    ft.pos = {base.x(), base.y(), base.z()};
    const Eigen::Quaterniond r(pose.rotation());
    ft.quat = {r.w(), r.x(), r.y(), r.z()};
    const std::string* at = perceived.location_of(t.name);
    ft.at = i == sim.held() ? "hand" : at ? *at : "none";
    f.things.push_back(std::move(ft));
  }
  return f;
}

}  // namespace rtamp::episode
