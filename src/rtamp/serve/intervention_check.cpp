#include "rtamp/serve/intervention_check.hpp"

#include <vector>

#include "rtamp/util/error.hpp"
#include "rtamp/world/intervention_rules.hpp"
#include "rtamp/world/names.hpp"
#include "rtamp/world/suggest.hpp"

namespace rtamp::serve {

using K = world::Intervention::Kind;

const char* kind_name(K k) { return world::intervention_kind_name(k, world::InterventionSyntax::Request); }

InterventionCheck::InterventionCheck(const world::Scenario& scenario) : scenario_(scenario) {
  const world::Vocabulary v(scenario, true);
  for (const auto& n : v.objects) ever_[n] = false;
  for (const auto& n : v.containers) ever_[n] = true;
  for (const auto& c : v.object_classes) classes_[c] = false;
  for (const auto& c : v.container_classes) classes_[c] = true;
  // The defaults of an add that names no class (scene_message.cpp offers them too).
  classes_.emplace("block", false);
  classes_.emplace("tray", true);
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
  world::InterventionWorld w;
  for (const auto& [n, t] : now.things) (t.container ? w.containers : w.objects)[n] = t.cls;
  w.ever = ever_;
  w.classes = classes_;
  for (const auto& [n, t] : now.things) {
    w.ever.emplace(n, t.container);
    w.classes.emplace(t.cls, t.container);
  }
  try {
    world::check_intervention(iv, scenario_, w, world::InterventionSyntax::Request,
                              std::string("intervention '") + kind_name(iv.kind) + "': ");
  } catch (const Error& e) {
    return e.message();
  }
  // Then what only a page is held to (a script may bring a class of its own).
  const bool adds = iv.kind == K::Add || iv.kind == K::AddContainer;
  if (adds && !iv.cls.empty() && !w.classes.count(iv.cls)) {
    std::vector<std::string> known;
    for (const auto& [c, container] : w.classes)
      if (container == (iv.kind == K::AddContainer)) known.push_back(c);
    return std::string("intervention '") + kind_name(iv.kind) + "': unknown class " + world::quoted(iv.cls) +
           " (a page adds things of the scenario's classes)" + world::suggestion(iv.cls, known);
  }
  return "";
}

}  // namespace rtamp::serve
