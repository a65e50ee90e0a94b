// A named choice: the names of an enum's values, each with a one-line
// description, in one table that every front end reads — the CLI (its
// choices and --help), the Python module and batch — so a choice is spelled
// in exactly one place. Each layer keeps the table beside its enum
// (e.g. exec::condition_modes() in exec/subtree_builder.hpp).
// Invariants: names are unique within a table; parse_name() accepts exactly
// the listed names.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "rtamp/util/error.hpp"

namespace rtamp {

template <class E>
struct Named {
  const char* name;
  E value;
  const char* description;  // one line, no final period
};

template <class E>
using NameTable = std::vector<Named<E>>;

// The value named `name`; rtamp::Error "unknown WHAT 'x' (expected one of: a, b)" otherwise.
template <class E>
E parse_name(const NameTable<E>& table, std::string_view name, std::string_view what) {
  std::string all;
  for (const auto& n : table) {
    if (name == n.name) return n.value;
    all += (all.empty() ? "" : ", ") + std::string(n.name);
  }
  throw Error("unknown " + std::string(what) + " '" + std::string(name) + "' (expected one of: " + all + ")");
}

// The name of `v` ("?" if the table lacks it).
template <class E>
const char* name_of(const NameTable<E>& table, E v) {
  for (const auto& n : table)
    if (n.value == v) return n.name;
  return "?";
}

}  // namespace rtamp
