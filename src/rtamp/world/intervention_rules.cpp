#include "rtamp/world/intervention_rules.hpp"

#include <sstream>
#include <vector>

#include "rtamp/world/geometry.hpp"
#include "rtamp/world/names.hpp"
#include "rtamp/world/suggest.hpp"
#include "rtamp/world/table.hpp"

namespace rtamp::world {

namespace {

using K = Intervention::Kind;

std::string fmt(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

std::vector<std::string> names_of(const std::map<std::string, std::string>& m) {
  std::vector<std::string> v;
  for (const auto& [n, c] : m) v.push_back(n);
  return v;
}

}  // namespace

const char* intervention_kind_name(K k, InterventionSyntax syntax) {
  const bool yaml = syntax == InterventionSyntax::Scenario;
  switch (k) {
    case K::Relocate: return "relocate";
    case K::Add: return "add";
    case K::Remove: return "remove";
    case K::AddContainer: return yaml ? "add_container" : "add-container";
    case K::RemoveContainer: return yaml ? "remove_container" : "remove-container";
    case K::TakeFromGripper: return yaml ? "take_from_gripper" : "take-from-gripper";
    case K::AddRegion: return yaml ? "add_region" : "add-region";
  }
  return "?";
}

void check_intervention(const Intervention& iv, const Scenario& s, const InterventionWorld& w,
                        InterventionSyntax syntax, const std::string& owner,
                        const std::function<SourceLocation(std::string_view field)>& locate) {
  const bool yaml = syntax == InterventionSyntax::Scenario;
  auto at = [&](std::string_view field) { return locate ? locate(field) : iv.where; };
  auto fail = [&](std::string_view field, const std::string& what) -> void { throw Error(owner + what, at(field)); };
  auto kind = [&](K k) { return intervention_kind_name(k, syntax); };

  const bool adds = iv.kind == K::Add || iv.kind == K::AddContainer;
  if (!adds && !iv.cls.empty())
    fail("", std::string("a class is only given to add and ") + kind(K::AddContainer));
  if (iv.kind == K::TakeFromGripper && !iv.subject.empty())
    fail("", std::string(kind(K::TakeFromGripper)) + " names no object (it takes whatever the gripper holds)");
  auto need_subject = [&](const char* field) {
    if (iv.subject.empty())
      fail("", yaml ? std::string("names no object (give ") + field + ": NAME)" : "names no object (give a 'subject')");
  };
  auto check_target = [&](bool subject_is_container) {
    if (iv.position)
      if (const std::string off = off_table(table_top(s), *iv.position); !off.empty()) fail("position", off);
    if (iv.location.empty()) {
      if (!iv.position && iv.kind != K::TakeFromGripper)
        fail("", yaml ? "needs a target: 'to: LOCATION' or 'position: [x, y, z]'"
                      : "needs a target: a 'location' or a 'position' [x, y, z]");
      return;
    }
    const Region* region = s.find_region(iv.location);
    if (!region) {
      if (w.containers.count(iv.location)) {
        if (subject_is_container)
          fail("to", "cannot put container " + quoted(iv.subject) + " into container " + quoted(iv.location) +
                         " (containers do not nest)");
        if (iv.location == iv.subject) fail("to", "cannot put " + quoted(iv.subject) + " into itself");
        return;
      }
      std::vector<std::string> locs;
      for (const Region& r : s.regions) locs.push_back(r.name);
      for (const auto& [n, c] : w.containers) locs.push_back(n);
      fail("to", "unknown location " + quoted(iv.location) + " at this time" + suggestion(iv.location, locs));
    }
    if (iv.position && !footprint(*region).contains_point((*iv.position)[0], (*iv.position)[1])) {
      const Vec3& p = *iv.position;
      fail("position", "position [" + fmt(p[0]) + ", " + fmt(p[1]) + ", " + fmt(p[2]) + "] is not inside region " +
                           quoted(iv.location));
    }
  };

  switch (iv.kind) {
    case K::Relocate: {
      need_subject("object");
      const bool is_obj = w.objects.count(iv.subject) > 0, is_cont = w.containers.count(iv.subject) > 0;
      if (!is_obj && !is_cont) {
        std::vector<std::string> all = names_of(w.objects);
        for (const auto& n : names_of(w.containers)) all.push_back(n);
        fail("object", "unknown object or container " + quoted(iv.subject) + " at this time" +
                           suggestion(iv.subject, all));
      }
      check_target(is_cont);
      return;
    }
    case K::Add:
    case K::AddContainer: {
      const bool cont = iv.kind == K::AddContainer;
      const char* field = cont ? "container" : "object";
      need_subject(field);
      check_new_name(iv.subject, owner + field, at(field));
      if (s.find_region(iv.subject) || w.objects.count(iv.subject) || w.containers.count(iv.subject))
        fail(field, quoted(iv.subject) + " already exists at this time");
      for (const Proposition& p : s.propositions)
        if (p.name == iv.subject) fail(field, quoted(iv.subject) + " is the name of a proposition");
      if (auto it = w.ever.find(iv.subject); it != w.ever.end() && it->second != cont)
        fail(field, quoted(iv.subject) + " was " + (cont ? "an object" : "a container") + " earlier; use a new name");
      check_class_name(iv.cls, owner.substr(0, owner.size() - 2), at("class"));
      if (auto it = w.classes.find(iv.cls); it != w.classes.end() && it->second != cont)
        fail("class", "class " + quoted(iv.cls) + " is already the class of " + (cont ? "objects" : "containers"));
      check_target(cont);
      return;
    }
    case K::Remove:
      need_subject("object");
      if (!w.objects.count(iv.subject))
        fail("object", "unknown object " + quoted(iv.subject) + " at this time" +
                           (w.containers.count(iv.subject)
                                ? std::string(" (it is a container: use ") + kind(K::RemoveContainer) + ")"
                                : suggestion(iv.subject, names_of(w.objects))));
      return;
    case K::RemoveContainer:
      need_subject("container");
      if (!w.containers.count(iv.subject))
        fail("container", "unknown container " + quoted(iv.subject) + " at this time" +
                              (w.objects.count(iv.subject) ? std::string(" (it is an object: use ") + kind(K::Remove) + ")"
                                                           : suggestion(iv.subject, names_of(w.containers))));
      return;
    case K::TakeFromGripper:
      check_target(false);
      return;
    case K::AddRegion:
      fail("", std::string("a person cannot add a region (") + kind(K::AddRegion) + " is a change for the planner)");
  }
}

void note_intervention(const Intervention& iv, InterventionWorld& w) {
  switch (iv.kind) {
    case K::Add:
    case K::AddContainer: {
      const bool cont = iv.kind == K::AddContainer;
      (cont ? w.containers : w.objects)[iv.subject] = iv.cls;
      w.ever.emplace(iv.subject, cont);
      w.classes.emplace(iv.cls, cont);
      return;
    }
    case K::Remove: w.objects.erase(iv.subject); return;
    case K::RemoveContainer: w.containers.erase(iv.subject); return;
    default: return;
  }
}

}  // namespace rtamp::world
