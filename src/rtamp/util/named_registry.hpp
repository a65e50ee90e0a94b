// A registry of named entries that front ends extend at run time (motion-cost
// models, worlds): add or replace by name, snapshots in registration order,
// lookup by name. Entry is a struct with a `std::string name`.
// Invariants: names are unique; safe to read and extend from several threads.
#pragma once

#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace rtamp {

template <class Entry>
class NamedRegistry {
 public:
  explicit NamedRegistry(std::vector<Entry> builtins = {}) : entries_(std::move(builtins)) {}

  // Adds `e`, or replaces the entry of the same name.
  void add(Entry e) {
    std::lock_guard lock(mutex_);
    for (auto& x : entries_)
      if (x.name == e.name) {
        x = std::move(e);
        return;
      }
    entries_.push_back(std::move(e));
  }
  std::vector<Entry> entries() const {
    std::lock_guard lock(mutex_);
    return entries_;
  }
  std::vector<std::string> names() const {
    std::lock_guard lock(mutex_);
    std::vector<std::string> out;
    for (const auto& x : entries_) out.push_back(x.name);
    return out;
  }
  std::optional<Entry> find(std::string_view name) const {
    std::lock_guard lock(mutex_);
    for (const auto& x : entries_)
      if (x.name == name) return x;
    return std::nullopt;
  }

 private:
  mutable std::mutex mutex_;
  std::vector<Entry> entries_;
};

}  // namespace rtamp
