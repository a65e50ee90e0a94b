// rtamp::bt::Blackboard — the typed key/value store shared by the nodes of a
// tree (py_trees / BehaviorTree.CPP "blackboard"). The paper's State Update
// decorator writes the current symbolic state here (Section III.D).
//
// Invariants:
//  - a key holds one C++ type for its whole life: set<T> on a key that holds
//    another type, or get<T> with the wrong T, throws BlackboardError naming the
//    key, the stored type and the requested type; get on a missing key throws too;
//  - entries are stable in memory until erased, so Entry<T> handles (resolved
//    once, then read/written without hashing) stay valid until erase(key) or
//    clear();
//  - reading or assigning an existing entry of a trivially copyable type does not
//    allocate (the hot path of a tick).
// Not thread-safe: a tree and its blackboard are used from one thread.
#pragma once

#include <any>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <typeindex>
#include <typeinfo>
#include <unordered_map>
#include <utility>
#include <vector>

#include "rtamp/util/error.hpp"

namespace rtamp::bt {

// A blackboard misuse: missing key, or a type that does not match the stored one.
class BlackboardError : public rtamp::Error {
 public:
  using rtamp::Error::Error;
};

// Human-readable (demangled) name of a C++ type, e.g. "std::vector<int, std::allocator<int> >".
std::string type_name(const std::type_info& type);

class Blackboard {
  struct Slot {
    std::any value;
    std::type_index type;
  };

 public:
  // A resolved entry: reads and writes without looking the key up again.
  template <class T>
  class Entry {
   public:
    Entry() = default;
    const T& get() const { return *std::any_cast<T>(&slot_->value); }
    T& get() { return *std::any_cast<T>(&slot_->value); }
    void set(T value) { get() = std::move(value); }
    explicit operator bool() const { return slot_ != nullptr; }

   private:
    friend class Blackboard;
    explicit Entry(Slot* slot) : slot_(slot) {}
    Slot* slot_ = nullptr;
  };

  Blackboard() = default;
  Blackboard(const Blackboard&) = delete;
  Blackboard& operator=(const Blackboard&) = delete;

  // Creates the entry, or assigns it if it exists with the same type.
  template <class T>
  void set(std::string_view key, T value) {
    using V = std::decay_t<T>;
    if (auto it = map_.find(key); it != map_.end()) {
      check_type(key, it->second, typeid(V));
      *std::any_cast<V>(&it->second.value) = std::move(value);
      return;
    }
    map_.emplace(std::string(key), Slot{std::any(std::in_place_type<V>, std::move(value)), typeid(V)});
  }

  // The value; throws BlackboardError if the key is missing or holds another type.
  template <class T>
  const T& get(std::string_view key) const {
    const Slot& slot = find_slot(key);
    check_type(key, slot, typeid(T));
    return *std::any_cast<T>(&slot.value);
  }
  template <class T>
  T& get(std::string_view key) {
    Slot& slot = const_cast<Slot&>(find_slot(key));
    check_type(key, slot, typeid(T));
    return *std::any_cast<T>(&slot.value);
  }

  // Pointer to the value, nullptr if the key is missing; throws if it holds another type.
  template <class T>
  const T* find(std::string_view key) const {
    auto it = map_.find(key);
    if (it == map_.end()) return nullptr;
    check_type(key, it->second, typeid(T));
    return std::any_cast<T>(&it->second.value);
  }

  // A handle to the entry, created with `initial` if missing; throws on a type mismatch.
  template <class T>
  Entry<T> entry(std::string_view key, T initial = T{}) {
    auto it = map_.find(key);
    if (it == map_.end()) {
      it =
          map_.emplace(std::string(key), Slot{std::any(std::in_place_type<T>, std::move(initial)), typeid(T)})
              .first;
    } else {
      check_type(key, it->second, typeid(T));
    }
    return Entry<T>(&it->second);
  }

  bool contains(std::string_view key) const { return map_.find(key) != map_.end(); }
  // Demangled name of the stored type; throws if the key is missing.
  std::string type_of(std::string_view key) const;
  // Removes the entry (invalidates its Entry handles). Returns whether it existed.
  bool erase(std::string_view key);
  void clear() { map_.clear(); }
  std::size_t size() const { return map_.size(); }
  // Keys in sorted order.
  std::vector<std::string> keys() const;

 private:
  struct Hash {
    using is_transparent = void;
    std::size_t operator()(std::string_view s) const { return std::hash<std::string_view>{}(s); }
  };
  const Slot& find_slot(std::string_view key) const;
  static void check_type(std::string_view key, const Slot& slot, const std::type_info& wanted) {
    if (slot.type != std::type_index(wanted)) throw_type_mismatch(key, slot, wanted);
  }
  [[noreturn]] static void throw_type_mismatch(std::string_view key, const Slot& slot,
                                               const std::type_info& wanted);

  std::unordered_map<std::string, Slot, Hash, std::equal_to<>> map_;
};

}  // namespace rtamp::bt
