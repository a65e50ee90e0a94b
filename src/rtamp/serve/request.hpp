// The page's requests (docs/serve.md "page → server") parsed from WebSocket
// text, and the `reply` every request gets. parse_request() never throws: a
// text that is not one JSON object with a known `type` and well-typed fields
// is a Request with `error` set (the reply's message), and its `id` when one
// could be read. Names are not checked here (intervention_check.hpp does that
// against the world as it is when the request is applied).
#pragma once

#include <optional>
#include <string>

#include "rtamp/world/scenario.hpp"

namespace rtamp::serve {

struct Request {
  enum class Type { Intervene, Control, Task, Invalid };
  Type type = Type::Invalid;
  std::string id = "null";  // the request's id as JSON text (echoed in the reply)
  std::string error;        // Invalid: why
  // Intervene: kind, subject, class, location, position (time unused).
  world::Intervention intervention;
  // Control: "pause" | "resume" | "step" | "speed" | "seek"; `value` for speed and seek.
  std::string action;
  std::optional<double> value;
  // Task: the new task's LTL formula (non-empty).
  std::string task;
};

Request parse_request(const std::string& text);

// {"type":"reply","id":ID,"ok":true} or with "error"; `extra` (a JSON object's
// members without braces, e.g. "\"server_ms\":0.4") is appended when not empty.
std::string reply_message(const std::string& id, bool ok, const std::string& error = {},
                          const std::string& extra = {});

}  // namespace rtamp::serve
