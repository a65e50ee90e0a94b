#include "rtamp/serve/paced_world.hpp"

#include <algorithm>

namespace rtamp::serve {

void PacedWorld::advance(double dt) {
  const double target = inner_.time() + std::max(0.0, dt);
  bool stepping = false;
  for (;;) {
    if (!stepping && playback_.hold(service_)) stepping = true;
    service_();
    if (changed_ && changed_()) break;  // the loop looks at the change now
    const double now = inner_.time();
    const double speed = playback_.speed();
    const double end = (stepping || speed <= 0 || playback_.stopped()) ? target : std::min(target, now + speed / 30);
    if (end > now) inner_.advance(end - now);
    if (!stepping) playback_.pace(inner_.time(), service_);
    after_slice_();
    if (end >= target) break;
    if (changed_ && changed_()) break;
  }
}

}  // namespace rtamp::serve
