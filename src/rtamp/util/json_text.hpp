// JSON text written directly, for what is written many times a second on an
// episode's loop thread — a served episode's frames and tree messages, the
// episode log's `tick` records: a few times fewer instructions than building
// an nlohmann::json and dumping it (docs/benchmarks.md "server overhead"). The text reads back as nlohmann's
// dump of the same values would: strings escaped (", \ and control
// characters; each byte that is not part of valid UTF-8 replaced by U+FFFD,
// so a WebSocket text frame always holds UTF-8), numbers in the shortest form that reads back
// to the same double, non-finite ones as null.
#pragma once

#include <string>
#include <string_view>

namespace rtamp::json_text {

// Appends "s" (quoted, escaped).
void append_string(std::string& out, std::string_view s);
// Appends v.
void append_number(std::string& out, double v);

}  // namespace rtamp::json_text
