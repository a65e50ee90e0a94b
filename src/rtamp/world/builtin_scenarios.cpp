#include "rtamp/world/builtin_scenarios.hpp"

#include <utility>

namespace rtamp::world {

namespace detail {
// Defined in the generated embedded_scenarios.cpp.
std::vector<std::pair<std::string_view, std::string_view>> embedded_scenarios();
}  // namespace detail

std::vector<std::string> builtin_scenario_names() {
  std::vector<std::string> names;
  for (const auto& [name, text] : detail::embedded_scenarios()) names.emplace_back(name);
  return names;
}

std::optional<std::string_view> builtin_scenario_text(std::string_view name) {
  for (const auto& [n, text] : detail::embedded_scenarios())
    if (n == name) return text;
  return std::nullopt;
}

}  // namespace rtamp::world
