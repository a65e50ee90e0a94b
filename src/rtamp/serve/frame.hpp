// A frame of the scene (exec/frame.hpp) as text: the `frame` message to
// pages (docs/serve.md "frame") and, at a low rate, the `frame` record of a
// served episode's log (docs/exec.md), which replays read back.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "rtamp/exec/frame.hpp"

namespace rtamp::serve {

using exec::Frame;

// {"type":"frame",...}: full precision for pages.
std::string frame_message(const Frame& f);
// {"ev":"frame",...} without "t" (EpisodeLog::record adds it): millimetres and
// milliradians, for the log.
std::string frame_record(const Frame& f);
// A log's frame record (parsed JSON text) as a frame message (rtamp::Error if it is not one).
std::string frame_message_from_record(const std::string& record);

}  // namespace rtamp::serve
