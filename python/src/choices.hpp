// The names Python uses for rtamp's enums, one table each (the same spellings
// as the CLI: "astar-exp", "online", "worker", "relocate", ...). parse_choice /
// choice_name (bindings.hpp) read them.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include "rtamp/episode/episode.hpp"
#include "rtamp/exec/reactive_loop.hpp"
#include "rtamp/exec/symbolic_world.hpp"
#include "rtamp/plan/search.hpp"
#include "rtamp/world/scenario.hpp"

namespace rtamp::python {

template <class E>
using Choices = std::vector<std::pair<const char*, E>>;

extern const Choices<plan::GraphConstruction> kGraphs;
extern const Choices<exec::ConditionMode> kConditions;
extern const Choices<exec::Reconfiguration> kReconfigurations;
extern const Choices<exec::PlanningMode> kPlanning;
extern const Choices<exec::MoveStatus> kMoveStatus;
extern const Choices<exec::Phase> kPhases;
extern const Choices<episode::WorldKind> kWorlds;
extern const Choices<world::Intervention::Kind> kInterventionKinds;

// kInterventionKinds by name (rtamp::Error for others) and back.
world::Intervention::Kind parse_intervention_kind(const std::string& s);
const char* intervention_kind_name(world::Intervention::Kind k);

}  // namespace rtamp::python
