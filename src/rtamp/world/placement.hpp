// Placement: where every movable thing is, symbolically — a map from a thing's
// name to the name of the location holding it (a region or a container), with
// the thing's class. This is the paper's state s = o1r1_o2r3_... (Section II)
// in its plainest form: the reference representation that proposition
// expressions are evaluated over (propositions.hpp) and that geometry.hpp's
// initial_placement() produces. The task layer packs states far more tightly;
// it tests its compiled labelling against evaluate() over this type.
//
// Invariants: none beyond the map's (one entry per thing). A location may be
// any string, including names no proposition mentions ("none", "hand").
#pragma once

#include <map>
#include <string>

namespace rtamp::world {

struct Placement {
  struct Thing {
    std::string location;    // region or container name ("none" if outside every location)
    std::string cls;         // class, e.g. "block", "tray"
    bool container = false;  // true for containers (trays)
    bool operator==(const Thing&) const = default;
  };
  std::map<std::string, Thing> things;

  void set(const std::string& name, std::string location, std::string cls, bool container = false) {
    things[name] = Thing{std::move(location), std::move(cls), container};
  }
  // Location of `name`, or nullptr if there is no such thing.
  const std::string* location_of(const std::string& name) const {
    auto it = things.find(name);
    return it == things.end() ? nullptr : &it->second.location;
  }
  bool operator==(const Placement&) const = default;
};

}  // namespace rtamp::world
