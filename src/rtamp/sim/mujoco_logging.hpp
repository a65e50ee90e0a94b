// MuJoCo's warning output, redirected on request. MuJoCo 2.2.2's default
// warning handler prints each warning and appends it to MUJOCO_LOG.TXT in the
// current directory; the counters in mjData (mjData::warning) are what rtamp
// reports, so the CLI keeps warnings only there. The sim layer never installs
// the handler on its own (linking or using rtamp has no process-wide effect):
// the rtamp CLI calls install_mujoco_log_handler() at start-up, a program that
// embeds rtamp decides for itself (docs/library.md).
#pragma once

namespace rtamp::sim {

// Sets MuJoCo's process-wide mju_user_warning to a handler that drops the text
// (the warning is still counted in mjData). Errors (mju_user_error) are left to
// MuJoCo. Idempotent; call it before any simulation runs (the hook is a plain
// global that MuJoCo reads from every thread).
void install_mujoco_log_handler();

}  // namespace rtamp::sim
