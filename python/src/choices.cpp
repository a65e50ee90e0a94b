// The enum name tables of choices.hpp.
#include "choices.hpp"

namespace rtamp::python {

const Choices<plan::GraphConstruction> kGraphs = {
    {"partial", plan::GraphConstruction::Partial},
    {"full", plan::GraphConstruction::Full},
};
const Choices<exec::ConditionMode> kConditions = {
    {"action", exec::ConditionMode::Action},
    {"state", exec::ConditionMode::State},
};
const Choices<exec::Reconfiguration> kReconfigurations = {
    {"online", exec::Reconfiguration::Online},
    {"offline", exec::Reconfiguration::Offline},
};
const Choices<exec::PlanningMode> kPlanning = {
    {"worker", exec::PlanningMode::Worker},
    {"inline", exec::PlanningMode::Inline},
};
const Choices<exec::MoveStatus> kMoveStatus = {
    {"idle", exec::MoveStatus::Idle},
    {"running", exec::MoveStatus::Running},
    {"succeeded", exec::MoveStatus::Succeeded},
    {"failed", exec::MoveStatus::Failed},
};
const Choices<exec::Phase> kPhases = {
    {"idle", exec::Phase::Idle},   {"approach", exec::Phase::Approach}, {"grasp", exec::Phase::Grasp},
    {"carry", exec::Phase::Carry}, {"place", exec::Phase::Place},       {"retreat", exec::Phase::Retreat},
    {"return", exec::Phase::Return},
};
const Choices<episode::WorldKind> kWorlds = {
    {"mujoco", episode::WorldKind::MuJoCo},
    {"symbolic", episode::WorldKind::Symbolic},
};
const Choices<world::Intervention::Kind> kInterventionKinds = {
    {"relocate", world::Intervention::Kind::Relocate},
    {"add", world::Intervention::Kind::Add},
    {"remove", world::Intervention::Kind::Remove},
    {"add-container", world::Intervention::Kind::AddContainer},
    {"remove-container", world::Intervention::Kind::RemoveContainer},
    {"take-from-gripper", world::Intervention::Kind::TakeFromGripper},
};

}  // namespace rtamp::python
