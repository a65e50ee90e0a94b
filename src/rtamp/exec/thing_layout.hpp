// Where to draw things whose world knows only their locations — the symbolic
// world, a user's world without frames of its own, and replays of logs
// without `frame` records (docs/serve.md "Frames"):
// each thing gets a spot (the centre of its base) inside its location, kept
// while it stays there. A thing at its initial location keeps its scenario
// position; a thing that arrives somewhere takes the first free cell of a grid
// over the location's footprint (contents of a container move with it); a held
// thing hangs under the hand; a thing at "none" keeps its last spot.
// frame() is the whole frame of such a world: update(), then every thing at its spot.
// Invariant: two things put in the same location by update() never share a
// grid cell while the location has a free one.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "rtamp/exec/frame.hpp"
#include "rtamp/world/placement.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::exec {

class ThingLayout {
 public:
  explicit ThingLayout(const world::Scenario& scenario);

  // Re-places what moved in `p` (held things: at `hand`, if known).
  void update(const world::Placement& p, const std::optional<world::Vec3>& hand = std::nullopt);
  // The spot of a thing of the last update (the centre of its base).
  world::Vec3 position(const std::string& thing) const;
  // The frame at time t of the things of `p` (update(p, hand) first): no joint
  // angles, the tool point at `hand`, the thing at "hand" held.
  Frame frame(double t, const world::Placement& p, const world::Vec3& hand);
  // Size of a thing: its scenario size, else that of the first scenario thing of its class, else the default.
  world::Vec3 size(const std::string& thing, const std::string& cls, bool container) const;

 private:
  struct Spot {
    std::string location;
    world::Vec3 pos{0, 0, 0};     // absolute (regions, none, hand)
    world::Vec3 offset{0, 0, 0};  // from the container's base centre (in a container)
  };
  world::Vec3 free_cell(const std::string& thing, const world::Vec3& size, const world::Vec3& centre,
                        const world::Vec3& extent, const world::Placement& p, bool relative);

  world::Scenario scenario_;
  world::Placement initial_;
  std::map<std::string, Spot> spots_;
  std::map<std::string, world::Vec3> sizes_;  // scenario things
};

}  // namespace rtamp::exec
