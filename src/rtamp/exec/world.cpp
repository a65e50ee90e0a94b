#include "rtamp/exec/world.hpp"

namespace rtamp::exec {

const char* to_string(MoveStatus s) {
  switch (s) {
    case MoveStatus::Idle: return "idle";
    case MoveStatus::Running: return "running";
    case MoveStatus::Succeeded: return "succeeded";
    case MoveStatus::Failed: return "failed";
  }
  return "?";
}

const char* to_string(world::Intervention::Kind k) {
  switch (k) {
    case world::Intervention::Kind::Relocate: return "relocate";
    case world::Intervention::Kind::Add: return "add";
    case world::Intervention::Kind::Remove: return "remove";
    case world::Intervention::Kind::AddContainer: return "add-container";
    case world::Intervention::Kind::RemoveContainer: return "remove-container";
    case world::Intervention::Kind::TakeFromGripper: return "take-from-gripper";
  }
  return "?";
}

}  // namespace rtamp::exec
