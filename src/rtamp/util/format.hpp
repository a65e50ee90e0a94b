// One way to write numbers and untrusted text in messages (the CLI's errors,
// help texts and summaries): numbers with the digits that matter, durations
// with a unit that fits, input echoed with its control bytes escaped.
//
//   format_number(60) == "60", format_number(0.0012345) == "0.001234",
//   format_number(1e20) == "1e+20", format_number(inf) == "inf"
//   format_seconds(120) == "120 s", format_seconds(0.018674159) == "18.7 ms",
//   format_seconds(3.7e-5) == "37 us"
//   format_count(5000000) == "5,000,000", format_bytes(4294967296) == "4 GiB"
//   escape_text("a\x1b[2Jb") == "a\\x1b[2Jb"
//
// Invariants: the results contain no control bytes and no newline; numbers
// are never printed with trailing zeros ("120.000000").
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <string_view>

namespace rtamp {

// `v` with at most `digits` significant digits, no trailing zeros; integers up
// to 10^15 in full; "inf", "-inf", "nan".
inline std::string format_number(double v, int digits = 4) {
  if (std::isnan(v)) return "nan";
  if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
  char b[64];
  if (v == std::floor(v) && std::fabs(v) < 1e15) {
    std::snprintf(b, sizeof b, "%.0f", v);
  } else {
    std::snprintf(b, sizeof b, "%.*g", digits, v);
  }
  return b;
}

// A duration with a unit that fits: "37 us", "18.7 ms", "2.35 s", "120 s",
// "1.5e+04 s" (3 significant digits, no trailing zeros).
inline std::string format_seconds(double s) {
  if (!std::isfinite(s)) return format_number(s) + " s";
  const double a = std::fabs(s);
  if (a > 0 && a < 1e-3) return format_number(s * 1e6, 3) + " us";
  if (a > 0 && a < 1) return format_number(s * 1e3, 3) + " ms";
  return format_number(s, 3) + " s";
}

// A count with thousands separators: "5,000,000".
inline std::string format_count(unsigned long long n) {
  std::string digits = std::to_string(n), out;
  for (std::size_t i = 0; i < digits.size(); ++i) {
    if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
    out += digits[i];
  }
  return out;
}

// Bytes in the binary unit that fits: "512 B", "1.5 KiB", "300 MiB", "4 GiB"
// (3 significant digits, no trailing zeros).
inline std::string format_bytes(double bytes) {
  static const char* units[] = {"B", "KiB", "MiB", "GiB", "TiB", "PiB"};
  int u = 0;
  while (u < 5 && std::fabs(bytes) >= 1024) bytes /= 1024, ++u;
  return format_number(bytes, 3) + " " + units[u];
}

// `text` with its control bytes (below 0x20, and 0x7f) written as \xHH; every
// other byte (UTF-8 included) passes unchanged.
inline std::string escape_text(std::string_view text) {
  static const char* hex = "0123456789abcdef";
  std::string out;
  out.reserve(text.size());
  for (const char ch : text) {
    const auto c = static_cast<unsigned char>(ch);
    if (c < 0x20 || c == 0x7f) {
      out += "\\x";
      out += hex[c >> 4];
      out += hex[c & 15];
    } else {
      out += ch;
    }
  }
  return out;
}

}  // namespace rtamp
