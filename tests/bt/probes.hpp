// Test helpers: actions and conditions whose outcome the test controls and whose
// calls it counts.
#pragma once

#include <memory>
#include <string>

#include "rtamp/bt/bt.hpp"

namespace rtamp::bt::testing {

struct Probe {
  Status next = Status::Success;  // what on_start / on_running return
  int starts = 0;
  int runs = 0;
  int halts = 0;
  int ticks() const { return starts + runs; }
};

inline std::unique_ptr<Action> probe_action(std::string name, Probe& p, std::string type_id = "Probe") {
  return std::make_unique<Action>(std::move(name),
                                  Action::Callbacks{[&p](Node&) {
                                                      ++p.starts;
                                                      return p.next;
                                                    },
                                                    [&p](Node&) {
                                                      ++p.runs;
                                                      return p.next;
                                                    },
                                                    [&p](Node&) { ++p.halts; }},
                                  std::move(type_id));
}

struct Flag {
  bool value = true;
  int checks = 0;
};

inline std::unique_ptr<Condition> flag_condition(std::string name, Flag& f, std::string type_id = "Flag") {
  return std::make_unique<Condition>(
      std::move(name),
      [&f](Node&) {
        ++f.checks;
        return f.value;
      },
      std::move(type_id));
}

template <class T, class... Children>
std::unique_ptr<T> make(std::string name, Children... children) {
  auto n = std::make_unique<T>(std::move(name));
  (n->add(std::move(children)), ...);
  return n;
}

}  // namespace rtamp::bt::testing
