// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// SplitMix64 (Steele, Lea, Flood 2014): the library's one seeded generator, the same on every
/// platform (the distributions of <random> are not), and its mixing function, which also turns a
/// grasp's identity into a seed (internal).
#pragma once

#include <cstdint>
#include <string_view>

namespace topograsp::detail {

/// The SplitMix64 finaliser: a bijective mix of the 64 bits of \p z.
[[nodiscard]] constexpr std::uint64_t splitmix64_mix(std::uint64_t z) noexcept {
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

/// The 64-bit FNV-1a hash of \p text.
[[nodiscard]] constexpr std::uint64_t fnv1a_64(std::string_view text) noexcept {
  std::uint64_t h = 0xcbf29ce484222325ull;
  for (const char c : text) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ull;
  }
  return h;
}

/// The SplitMix64 generator over a 64-bit state.
struct SplitMix64 {
  std::uint64_t state;
  /// The next 64 random bits.
  constexpr std::uint64_t next() noexcept { return splitmix64_mix(state += 0x9e3779b97f4a7c15ull); }
  /// Uniform in [0, 1).
  constexpr double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
};

}  // namespace topograsp::detail
