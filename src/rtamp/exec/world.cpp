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

}  // namespace rtamp::exec
