#include "rtamp/bt/blackboard.hpp"

#include <cxxabi.h>

#include <algorithm>
#include <cstdlib>

namespace rtamp::bt {

std::string type_name(const std::type_info& type) {
  int status = 0;
  char* demangled = abi::__cxa_demangle(type.name(), nullptr, nullptr, &status);
  std::string out = (status == 0 && demangled != nullptr) ? std::string(demangled) : std::string(type.name());
  std::free(demangled);
  // The libstdc++ spelling of std::string is long; users know it as std::string.
  const std::string long_string =
      "std::__cxx11::basic_string<char, std::char_traits<char>, std::allocator<char> >";
  for (std::size_t at = out.find(long_string); at != std::string::npos; at = out.find(long_string, at)) {
    out.replace(at, long_string.size(), "std::string");
  }
  return out;
}

const Blackboard::Slot& Blackboard::find_slot(std::string_view key) const {
  auto it = map_.find(key);
  if (it == map_.end()) throw BlackboardError("blackboard has no key '" + std::string(key) + "'");
  return it->second;
}

void Blackboard::throw_type_mismatch(std::string_view key, const Slot& slot, const std::type_info& wanted) {
  throw BlackboardError("blackboard key '" + std::string(key) + "' holds a value of type '" +
                        type_name(slot.value.type()) + "', not '" + type_name(wanted) + "'");
}

std::string Blackboard::type_of(std::string_view key) const { return type_name(find_slot(key).value.type()); }

bool Blackboard::erase(std::string_view key) {
  auto it = map_.find(key);
  if (it == map_.end()) return false;
  map_.erase(it);
  return true;
}

std::vector<std::string> Blackboard::keys() const {
  std::vector<std::string> out;
  out.reserve(map_.size());
  for (const auto& [k, v] : map_) out.push_back(k);
  std::sort(out.begin(), out.end());
  return out;
}

}  // namespace rtamp::bt
