#include "rtamp/world/scenario.hpp"

namespace rtamp::world {

namespace {
template <class T>
const T* find_named(const std::vector<T>& items, const std::string& n) {
  for (const T& item : items)
    if (item.name == n) return &item;
  return nullptr;
}
}  // namespace

const Region* Scenario::find_region(const std::string& n) const { return find_named(regions, n); }
const Container* Scenario::find_container(const std::string& n) const { return find_named(containers, n); }
const Object* Scenario::find_object(const std::string& n) const { return find_named(objects, n); }
const Proposition* Scenario::find_proposition(const std::string& n) const { return find_named(propositions, n); }
const ClassColour* Scenario::find_colour(const std::string& cls) const {
  for (const ClassColour& c : colours)
    if (c.cls == cls) return &c;
  return nullptr;
}

}  // namespace rtamp::world
