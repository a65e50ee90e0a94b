// The world a served episode's loop sees: an exec::World that forwards
// everything to the real one (MuJoCo or symbolic) but lets time pass in
// slices paced to wall time (Playback: speed, pause, step), so a page watches
// the episode as it happens. Between slices — and while paused — it calls
// `service` (apply the pages' interventions: on the loop's thread, through the
// world, as a scripted operator's are) and `after_slice` (frames).
//
// A slice is at most speed / 30 s of world time (30 frames a wall second); a
// discrete-event world's jump (next_event_time) is cut into slices too, so a
// page's intervention waits at most one slice. Slicing does not change what
// happens: a world's advance(a) then advance(b) processes the same events as
// advance(a + b) (exec/world.hpp), so an unhindered served episode ends as
// `rtamp run` does. At speed 0 (as fast as possible) and for a granted step
// the whole dt is one slice, unpaced.
//
// An intervention a page made (`changed()` true after `service`: applied, or
// refused by the world) ends advance() early, after the slice it happened in:
// the loop observes it at once (logs it at the time it took effect, reacts)
// instead of after the rest of a discrete-event jump, whose frame records would
// precede it in the log; the loop then asks again from the new time
// (exec/world.hpp lets advance() stop at any change).
#pragma once

#include <functional>

#include "rtamp/exec/world.hpp"
#include "rtamp/serve/playback.hpp"

namespace rtamp::serve {

class PacedWorld final : public exec::World {
 public:
  PacedWorld(exec::World& inner, Playback& playback, std::function<void()> service, std::function<void()> after_slice,
             std::function<bool()> changed = {})
      : inner_(inner), playback_(playback), service_(std::move(service)), after_slice_(std::move(after_slice)),
        changed_(std::move(changed)) {}

  double time() const override { return inner_.time(); }
  void advance(double dt) override;
  double next_event_time() const override { return inner_.next_event_time(); }
  world::Placement observe() override { return inner_.observe(); }
  bool confirming() const override { return inner_.confirming(); }
  void start(const exec::Move& m) override { inner_.start(m); }
  exec::MoveStatus poll(std::string* why) override { return inner_.poll(why); }
  void halt() override { inner_.halt(); }
  bool busy() override { return inner_.busy(); }
  std::string hand() const override { return inner_.hand(); }
  double distance_travelled() const override { return inner_.distance_travelled(); }
  std::vector<exec::WorldEvent> take_events() override { return inner_.take_events(); }
  exec::Intervenable* intervenable() override { return inner_.intervenable(); }
  exec::FrameSource* frames() override { return inner_.frames(); }

 private:
  exec::World& inner_;
  Playback& playback_;
  std::function<void()> service_, after_slice_;
  std::function<bool()> changed_;  // true once after a page changed the world
};

}  // namespace rtamp::serve
