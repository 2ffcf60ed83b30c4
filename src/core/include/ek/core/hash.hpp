#pragma once
/// \file
/// SplitMix64 (Steele, Lea and Flood 2014): the 64-bit finaliser used for
/// seeds derived from other seeds, and a tiny counter-based generator for the
/// few places that need reproducible numbers without a GSL generator.
#include <cstdint>

namespace ek {

/// SplitMix64 output for state x: finalise(x + golden gamma).
inline std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ULL;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
  return x ^ (x >> 31);
}

/// The next SplitMix64 number of a sequence; advances `state`.
inline std::uint64_t splitmix64_next(std::uint64_t& state) {
  const std::uint64_t r = splitmix64(state);
  state += 0x9E3779B97F4A7C15ULL;
  return r;
}

/// A uniform double in [0, 1) from the next 53 bits of the sequence.
inline double splitmix64_uniform(std::uint64_t& state) {
  return static_cast<double>(splitmix64_next(state) >> 11) * 0x1.0p-53;
}

}  // namespace ek
