#include "rtamp/serve/intervention_check.hpp"

#include <vector>

#include "rtamp/util/error.hpp"
#include "rtamp/world/geometry.hpp"
#include "rtamp/world/names.hpp"
#include "rtamp/world/suggest.hpp"

namespace rtamp::serve {

using K = world::Intervention::Kind;

const char* kind_name(K k) { return world::to_string(k); }

InterventionCheck::InterventionCheck(const world::Scenario& scenario) : scenario_(scenario) {
  const world::Vocabulary v(scenario, true);
  for (const auto& n : v.objects) ever_[n] = false;
  for (const auto& n : v.containers) ever_[n] = true;
  for (const auto& c : v.object_classes) classes_[c] = false;
  for (const auto& c : v.container_classes) classes_[c] = true;
}

void InterventionCheck::note(const world::Placement& now) {
  for (const auto& [n, t] : now.things) {
    ever_.emplace(n, t.container);
    classes_.emplace(t.cls, t.container);
  }
}

bool InterventionCheck::used(const std::string& name) const {
  if (ever_.count(name) || scenario_.find_region(name)) return true;
  for (const auto& p : scenario_.propositions)
    if (p.name == name) return true;
  return false;
}

std::string InterventionCheck::fresh_name(bool container) const {
  for (int n = 1;; ++n) {
    const std::string name = (container ? "t" : "o") + std::to_string(n);
    if (!used(name)) return name;
  }
}

std::string InterventionCheck::check(const world::Intervention& iv, const world::Placement& now) const {
  const std::string owner = std::string("intervention '") + kind_name(iv.kind) + "': ";
  auto present = [&](bool containers) {
    std::vector<std::string> v;
    for (const auto& [n, t] : now.things)
      if (t.container == containers) v.push_back(n);
    return v;
  };
  auto is_present = [&](const std::string& n, bool container) {
    auto it = now.things.find(n);
    return it != now.things.end() && it->second.container == container;
  };
  auto target = [&](bool subject_is_container, bool required) -> std::string {
    if (iv.location.empty()) {
      if (!iv.position && required) return owner + "needs a target: a 'location' or a 'position' [x, y, z]";
      return "";
    }
    const world::Region* region = scenario_.find_region(iv.location);
    if (!region) {
      if (is_present(iv.location, true)) {
        if (subject_is_container)
          return owner + "cannot put container " + world::quoted(iv.subject) + " into container " +
                 world::quoted(iv.location) + " (containers do not nest)";
        if (iv.location == iv.subject) return owner + "cannot put " + world::quoted(iv.subject) + " into itself";
        return "";
      }
      std::vector<std::string> locs;
      for (const auto& r : scenario_.regions) locs.push_back(r.name);
      for (const auto& c : present(true)) locs.push_back(c);
      return owner + "unknown location " + world::quoted(iv.location) + world::suggestion(iv.location, locs);
    }
    if (iv.position && !world::footprint(*region).contains_point((*iv.position)[0], (*iv.position)[1]))
      return owner + "position is not inside region " + world::quoted(iv.location);
    return "";
  };
  const bool adds = iv.kind == K::Add || iv.kind == K::AddContainer;
  if (!adds && !iv.cls.empty()) return owner + "a class is only given to add and add-container";
  if (iv.kind != K::TakeFromGripper && iv.subject.empty()) return owner + "names no 'subject'";
  switch (iv.kind) {
    case K::Relocate: {
      const bool obj = is_present(iv.subject, false), cont = is_present(iv.subject, true);
      if (!obj && !cont) {
        std::vector<std::string> all = present(false);
        for (const auto& c : present(true)) all.push_back(c);
        return owner + "unknown object or container " + world::quoted(iv.subject) + world::suggestion(iv.subject, all);
      }
      return target(cont, true);
    }
    case K::Add:
    case K::AddContainer: {
      const bool cont = iv.kind == K::AddContainer;
      try {
        world::check_new_name(iv.subject, owner + (cont ? "container" : "object"), {});
        world::check_class_name(iv.cls, owner.substr(0, owner.size() - 2), {});
      } catch (const Error& e) {
        return e.message();
      }
      if (scenario_.find_region(iv.subject) || now.things.count(iv.subject))
        return owner + world::quoted(iv.subject) + " already exists";
      for (const auto& p : scenario_.propositions)
        if (p.name == iv.subject) return owner + world::quoted(iv.subject) + " is the name of a proposition";
      if (auto it = ever_.find(iv.subject); it != ever_.end() && it->second != cont)
        return owner + world::quoted(iv.subject) + " was " + (cont ? "an object" : "a container") +
               " earlier; use a new name";
      if (auto it = classes_.find(iv.cls); it != classes_.end() && it->second != cont)
        return owner + "class " + world::quoted(iv.cls) + " is the class of " + (cont ? "objects" : "containers");
      return target(cont, true);
    }
    case K::Remove:
      if (!is_present(iv.subject, false))
        return owner + "unknown object " + world::quoted(iv.subject) +
               (is_present(iv.subject, true) ? " (it is a container: use remove-container)"
                                             : world::suggestion(iv.subject, present(false)));
      return "";
    case K::RemoveContainer:
      if (!is_present(iv.subject, true))
        return owner + "unknown container " + world::quoted(iv.subject) +
               (is_present(iv.subject, false) ? " (it is an object: use remove)"
                                              : world::suggestion(iv.subject, present(true)));
      return "";
    case K::TakeFromGripper:
      if (!iv.subject.empty())
        return owner + "names no subject (it takes whatever the gripper holds)";
      return target(false, false);
    case K::AddRegion:
      return owner + "a person cannot add a region (add-region is a change for the planner)";
  }
  return "";
}

}  // namespace rtamp::serve
