// OMPL's console output, made quiet on request. OMPL prints every planner's
// progress ("Info: RRTConnect: ...") through a process-wide output handler; the
// robot layer never changes it on its own (linking or using rtamp has no
// process-wide effect). The rtamp CLI calls quiet_ompl_logging() at start-up;
// a program that embeds rtamp decides for itself (docs/library.md).
#pragma once

namespace rtamp::robot {

// Sets OMPL's log level to errors only (ompl::msg::setLogLevel(LOG_ERROR)) for
// the whole process. Idempotent; call it before planning starts (OMPL's level
// is a plain global, not synchronised with planners running on other threads).
void quiet_ompl_logging();

}  // namespace rtamp::robot
