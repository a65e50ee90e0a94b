// Playback control of a served episode or replay (docs/serve.md "control"):
// speed (world seconds per wall second; 0 = as fast as possible), pause,
// resume and single steps, set from any thread (the server's), and the pacing
// the episode's (or replay's) own thread does with them: hold() blocks while
// paused, pace(t) sleeps until world time t is due at the current speed.
// Both wake at once when wake() is called (a request is waiting to be served
// on that thread) and call `service` then, and at least every 20 ms. A
// `service` that changed the world calls end_slice(): the pace() it runs in
// returns at once instead of at its due time, so the loop looks at the change
// without waiting out the slice (the anchor stays: later slices keep time).
//
// Pacing keeps an anchor (wall time, world time) and re-anchors after a pause,
// a speed change, or when the world falls more than 0.25 s of wall time
// behind (a world slower than real time runs as fast as it can; it does not
// race to catch up).
#pragma once

#include <chrono>
#include <condition_variable>
#include <functional>
#include <mutex>

namespace rtamp::serve {

class Playback {
 public:
  using Service = std::function<void()>;

  Playback(double speed, bool paused) : speed_(speed), paused_(paused) {}

  // Controls (any thread).
  void pause();
  void resume();
  void step();  // while paused: let one step through
  void set_speed(double speed);
  void wake();  // `service` is due on the playback thread
  void stop();  // every wait returns; stopped() from now on

  double speed() const;
  bool paused() const;
  bool stopped() const;

  // Playback thread. Blocks while paused; returns true if a step was granted
  // (the caller runs one step unpaced), false when playing (or stopped).
  bool hold(const Service& service);
  // Sleeps until world time `t` is due (at once for speed 0 or past t), or
  // until a `service` it ran called end_slice().
  void pace(double t, const Service& service);
  // Playback thread, from `service`: the pace() in progress returns now.
  void end_slice();

 private:
  using Clock = std::chrono::steady_clock;
  bool wait_locked(std::unique_lock<std::mutex>& lock, Clock::time_point until, const Service& service);

  mutable std::mutex mu_;
  std::condition_variable cv_;
  double speed_;
  bool paused_;
  int steps_ = 0;
  bool woken_ = false, stopped_ = false, reanchor_ = true, end_slice_ = false;
  Clock::time_point wall0_;
  double t0_ = 0, last_t_ = 0;
};

}  // namespace rtamp::serve
