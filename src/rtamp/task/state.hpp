// The symbolic state of the transition system (paper Definition 1, docs/design.md
// "Symbolic state") and its actions, as small packed value types.
//
// A State assigns every movable thing (object or container) a location (a
// fixed region or a container) and records the location of the robot's hand
// (where its last action ended, or "home" before the first action). Each of
// these is one *field* of `bits` bits; fields are packed into up to
// kStateWords 64-bit words (a field never straddles two words). The number of
// things is a run-time quantity; the Layout (owned by task::System) says how
// many bits, fields and words a state of that system uses.
// Invariants: bits of a State outside the system's fields are zero, so two
// states of the same system are equal iff their words are equal, and hashing
// the first `words` words is a valid hash.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

namespace rtamp::task {

inline constexpr std::size_t kStateWords = 4;  // at most 256 bits per state

struct State {
  std::array<std::uint64_t, kStateWords> words{};
  friend bool operator==(const State&, const State&) = default;
};

// Bit layout of a system's states. Field positions are tabulated by init()
// (no division on the hot path).
struct Layout {
  unsigned bits = 1;        // bits per field
  unsigned per_word = 64;   // fields per word
  unsigned num_fields = 0;  // things + 1 (the hand is the last field)
  unsigned words = 1;       // words in use (1..kStateWords); > kStateWords: too many fields

  Layout() { init(1, 0); }
  void init(unsigned field_bits, unsigned fields) {
    bits = field_bits;
    per_word = 64 / bits;
    num_fields = fields;
    words = std::max(1u, (num_fields + per_word - 1) / per_word);
    mask_ = bits >= 64 ? ~std::uint64_t{0} : ((std::uint64_t{1} << bits) - 1);
    for (unsigned f = 0; f < word_of_.size(); ++f) {
      word_of_[f] = static_cast<std::uint8_t>(std::min<unsigned>(f / per_word, kStateWords - 1));
      shift_of_[f] = static_cast<std::uint8_t>((f % per_word) * bits);
    }
  }
  std::uint32_t get(const State& s, unsigned field) const {
    return static_cast<std::uint32_t>((s.words[word_of_[field]] >> shift_of_[field]) & mask_);
  }
  void set(State& s, unsigned field, std::uint32_t v) const {
    std::uint64_t& w = s.words[word_of_[field]];
    w = (w & ~(mask_ << shift_of_[field])) | (std::uint64_t{v} << shift_of_[field]);
  }
  std::uint64_t mask() const { return mask_; }
  unsigned shift(unsigned field) const { return shift_of_[field]; }

 private:
  std::uint64_t mask_ = 1;
  std::array<std::uint8_t, kStateWords * 64> word_of_{}, shift_of_{};
};

// Hash of the first `words` words (a multiply-xorshift mix).
inline std::uint64_t hash_words(const std::uint64_t* w, unsigned words, std::uint64_t seed = 0) {
  std::uint64_t h = seed ^ 0x9e3779b97f4a7c15ull;
  for (unsigned i = 0; i < words; ++i) {
    h ^= w[i] + 0x9e3779b97f4a7c15ull + (h << 6) + (h >> 2);
    h *= 0xbf58476d1ce4e5b9ull;
    h ^= h >> 31;
  }
  h *= 0x94d049bb133111ebull;
  return h ^ (h >> 29);
}

// An action of the TS: move(thing, to) — pick the thing (object or container)
// wherever it is and place it at location `to` — or stay.
struct Action {
  enum class Kind : std::uint8_t { Stay, Move };
  Kind kind = Kind::Stay;
  std::uint16_t thing = 0;  // Move: index of the thing in task::System
  std::uint16_t to = 0;     // Move: index of the destination location
  static Action stay() { return {}; }
  static Action move(std::uint16_t thing, std::uint16_t to) { return {Kind::Move, thing, to}; }
  bool is_stay() const { return kind == Kind::Stay; }
  std::uint32_t packed() const {
    return is_stay() ? 0xffffffffu : (std::uint32_t{thing} << 16) | to;
  }
  static Action unpack(std::uint32_t p) {
    return p == 0xffffffffu ? stay() : move(static_cast<std::uint16_t>(p >> 16), static_cast<std::uint16_t>(p & 0xffff));
  }
  friend bool operator==(const Action&, const Action&) = default;
};

}  // namespace rtamp::task
