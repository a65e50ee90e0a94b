// Base64 (RFC 4648, the standard alphabet, '=' padding): how binary data (a PNG
// image) travels in JSON text — a Foxglove message's bytes field in a JSON MCAP
// channel, a page's `camera` message.
#pragma once

#include <string>
#include <string_view>

namespace rtamp::base64 {

// Appends the encoding of `bytes` to `out`.
void append(std::string& out, std::string_view bytes);

}  // namespace rtamp::base64
