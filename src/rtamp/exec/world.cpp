#include "rtamp/exec/world.hpp"

namespace rtamp::exec {

const NameTable<MoveStatus>& move_statuses() {
  static const NameTable<MoveStatus> t = {
      {"idle", MoveStatus::Idle, "no move started yet"},
      {"running", MoveStatus::Running, "the move is under way"},
      {"succeeded", MoveStatus::Succeeded, "the thing is at its destination"},
      {"failed", MoveStatus::Failed, "the move ended without placing its thing (poll's reason says why)"},
  };
  return t;
}

const char* to_string(MoveStatus s) { return name_of(move_statuses(), s); }

}  // namespace rtamp::exec
