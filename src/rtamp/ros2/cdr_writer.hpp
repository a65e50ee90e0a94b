// The CDR encoding of ROS 2 messages as DDS puts them on the wire and MCAP's
// ros2 profile stores them: XCDR1 (plain CDR), little-endian, after the 4-byte
// encapsulation header 00 01 00 00 (CDR_LE). Rules (OMG CDR, DDS-XTypes 7.4):
// a primitive is aligned to its size (1, 2, 4 or 8 bytes; bool, byte, char,
// int8, uint8: 1) counted from the first byte after the encapsulation header,
// padding with zero bytes; a string is a uint32 length that counts the
// terminating NUL, the bytes, then the NUL; a sequence is a uint32 element
// count, then the elements; a fixed array is its elements only; a nested
// message is its fields in order (no header, no padding of its own).
// The generated messages (rtamp/ros2/messages.hpp, from the .msg files) call it.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

namespace rtamp::ros2 {

class CdrWriter {
 public:
  CdrWriter() { buf_.assign("\x00\x01\x00\x00", 4); }

  template <typename T>
    requires std::is_arithmetic_v<T>
  void put(T v) {
    if constexpr (std::is_same_v<T, bool>) {
      buf_ += static_cast<char>(v ? 1 : 0);
    } else {
      align(sizeof(T));
      char bytes[sizeof(T)];
      std::memcpy(bytes, &v, sizeof(T));  // little-endian hosts only (checked below)
      buf_.append(bytes, sizeof(T));
    }
  }
  void put(const std::string& s) { put(std::string_view(s)); }
  void put(std::string_view s) {
    put(static_cast<std::uint32_t>(s.size() + 1));
    buf_.append(s);
    buf_ += '\0';
  }
  // A sequence's element count.
  void count(std::size_t n) { put(static_cast<std::uint32_t>(n)); }
  // Bytes (uint8[], byte[], char[]) in one go: no alignment inside.
  void put_bytes(const std::uint8_t* data, std::size_t n) { buf_.append(reinterpret_cast<const char*>(data), n); }

  // The encoded message, encapsulation header first.
  const std::string& bytes() const { return buf_; }
  std::string take() { return std::move(buf_); }

 private:
  void align(std::size_t n) {
    const std::size_t at = (buf_.size() - 4) % n;
    if (at) buf_.append(n - at, '\0');
  }
  std::string buf_;
};

static_assert(std::endian::native == std::endian::little, "the CDR writer writes little-endian by copying");

// A sequence bound (T[<=N], string<=N) exceeded: rtamp::Error naming the field.
[[noreturn]] void throw_bound(const char* field, std::size_t size, std::size_t bound);

// A whole message: the encapsulation header and the message's fields.
template <typename Message>
std::string encode(const Message& m) {
  CdrWriter w;
  write(w, m);
  return w.take();
}

}  // namespace rtamp::ros2
