#include "rtamp/exec/person_world.hpp"

#include <algorithm>
#include <cmath>

#include "rtamp/util/error.hpp"

namespace rtamp::exec {

namespace {

Intervenable& hands_of(World& w, const std::string& name) {
  Intervenable* h = w.intervenable();
  if (!h)
    throw Error(name + " cannot take a person's interventions (its World has no intervenable()): drop the "
                       "script, the random interventions and the random change, or use a world that can");
  return *h;
}

}  // namespace

PersonWorld::PersonWorld(World& inner, world::Person& person, const std::string& world_name)
    : ForwardingWorld(inner), hands_(hands_of(inner, world_name)), person_(person) {
  apply_due();
}

// The true placement (a noise-free perception in MuJoCo) is read only when
// something is due, not at every advance.
void PersonWorld::apply_due() {
  while (person_.next_time() <= inner_.time()) {
    const auto iv = person_.due(inner_.time(), hands_.true_placement());
    if (!iv) break;
    hands_.apply(*iv);
  }
}

void PersonWorld::advance(double dt) {
  const double target = inner_.time() + std::max(0.0, dt);
  apply_due();
  for (;;) {
    const double now = inner_.time();
    const double next = person_.next_time();
    if (!(next <= target) || now >= target) break;
    if (next > now) inner_.advance(next - now);
    apply_due();
  }
  if (const double left = target - inner_.time(); left > 1e-12) inner_.advance(left);
  apply_due();
}

double PersonWorld::next_event_time() const {
  const double inner = inner_.next_event_time();
  if (std::isinf(inner)) return inner;  // continuous or idle: the loop ticks it
  return std::min(inner, std::max(person_.next_time(), inner_.time()));
}

}  // namespace rtamp::exec
