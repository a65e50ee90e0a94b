// UTF-8 validity (RFC 3629: no overlong forms, no surrogates, nothing above
// U+10FFFF). Used wherever text leaves rtamp for tools that require UTF-8
// (JSON, Python strings) and to refuse input that is not UTF-8 where it must be.
#pragma once

#include <cstddef>
#include <string_view>

namespace rtamp::utf8 {

// Length of the valid UTF-8 sequence starting at s[i] (1 for ASCII), or 0
// when none starts there.
std::size_t sequence_length(std::string_view s, std::size_t i);

// Offset of the first byte that starts no valid sequence, or npos.
std::size_t first_invalid(std::string_view s);

}  // namespace rtamp::utf8
