#include "rtamp/serve/playback.hpp"

#include <algorithm>
#include <utility>

namespace rtamp::serve {

void Playback::pause() {
  std::lock_guard lock(mu_);
  paused_ = true;
  cv_.notify_all();
}

void Playback::resume() {
  std::lock_guard lock(mu_);
  paused_ = false;
  steps_ = 0;
  reanchor_ = true;
  cv_.notify_all();
}

void Playback::step() {
  std::lock_guard lock(mu_);
  ++steps_;
  cv_.notify_all();
}

void Playback::set_speed(double speed) {
  std::lock_guard lock(mu_);
  speed_ = speed;
  reanchor_ = true;
  cv_.notify_all();
}

void Playback::wake() {
  std::lock_guard lock(mu_);
  woken_ = true;
  cv_.notify_all();
}

void Playback::stop() {
  std::lock_guard lock(mu_);
  stopped_ = true;
  cv_.notify_all();
}

double Playback::speed() const {
  std::lock_guard lock(mu_);
  return speed_;
}

bool Playback::paused() const {
  std::lock_guard lock(mu_);
  return paused_;
}

bool Playback::stopped() const {
  std::lock_guard lock(mu_);
  return stopped_;
}

// Waits once: until `until`, a wake, a control change or 20 ms, whichever
// comes first; then runs `service` (unlocked) if woken or 20 ms passed. True
// when `until` has come. Callers re-check their condition after every return
// (a control change may have happened while `service` ran).
bool Playback::wait_locked(std::unique_lock<std::mutex>& lock, Clock::time_point until, const Service& service) {
  if (stopped_) return false;
  if (!woken_) {
    const auto now = Clock::now();
    if (now >= until) return true;
    const bool notified =
        cv_.wait_until(lock, std::min(until, now + std::chrono::milliseconds(20))) == std::cv_status::no_timeout;
    if (notified && !woken_) return false;  // a control changed
  }
  woken_ = false;
  lock.unlock();
  if (service) service();
  lock.lock();
  return Clock::now() >= until;
}

bool Playback::hold(const Service& service) {
  std::unique_lock lock(mu_);
  while (paused_ && !stopped_) {
    if (steps_ > 0) {
      --steps_;
      reanchor_ = true;
      return true;
    }
    wait_locked(lock, Clock::now() + std::chrono::hours(1), service);
  }
  return false;
}

void Playback::end_slice() {
  std::lock_guard lock(mu_);
  end_slice_ = true;
}

void Playback::pace(double t, const Service& service) {
  std::unique_lock lock(mu_);
  end_slice_ = false;  // a change before this slice was seen by its caller
  for (;;) {
    if (stopped_ || paused_ || speed_ <= 0) {
      last_t_ = t;
      reanchor_ = true;
      return;
    }
    const auto now = Clock::now();
    if (reanchor_) {
      wall0_ = now;
      t0_ = last_t_;
      reanchor_ = false;
    }
    const auto due = wall0_ + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>((t - t0_) / speed_));
    if (now > due + std::chrono::milliseconds(250)) {  // fallen behind: no racing to catch up
      wall0_ = now;
      t0_ = t;
    }
    if (now >= due) {
      last_t_ = t;
      return;
    }
    if (wait_locked(lock, due, service) || std::exchange(end_slice_, false)) {
      last_t_ = t;
      return;
    }
    // Interrupted by a control change: loop (re-anchors if needed, returns if paused).
  }
}

}  // namespace rtamp::serve
