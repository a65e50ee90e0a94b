#include "rtamp/sim/mujoco_logging.hpp"

#include <mujoco/mujoco.h>

namespace rtamp::sim {

namespace {
void quiet_warning(const char*) {}
}  // namespace

void install_mujoco_log_handler() { mju_user_warning = quiet_warning; }

}  // namespace rtamp::sim
