// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>
#include <topograsp/core/random.hpp>

using topograsp::detail::SplitMix64;
using topograsp::detail::splitmix64_mix;

TEST_CASE("SplitMix64 gives the reference sequence", "[core][random]") {
  // The first outputs of SplitMix64 seeded with 0 (Vigna's reference implementation, splitmix64.c).
  SplitMix64 rng{0};
  CHECK(rng.next() == 0xe220a8397b1dcdafull);
  CHECK(rng.next() == 0x6e789e6aa1b965f4ull);
  CHECK(rng.next() == 0x06c45d188009454full);
  STATIC_REQUIRE(splitmix64_mix(0x9e3779b97f4a7c15ull) == 0xe220a8397b1dcdafull);
}

TEST_CASE("SplitMix64's uniform numbers lie in [0, 1) and are reproducible", "[core][random]") {
  SplitMix64 a{42}, b{42};
  for (int i = 0; i < 1000; ++i) {
    const double u = a.uniform();
    CHECK(u >= 0.0);
    CHECK(u < 1.0);
    CHECK(u == b.uniform());
  }
}
