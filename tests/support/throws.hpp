// SPDX-License-Identifier: BSD-3-Clause
// check_throws_naming(): the bad-input check of every test of a public entry point.
#pragma once

#include <string>

#include <catch2/catch.hpp>
#include <topograsp/core/error.hpp>

namespace topograsp::test {

/// Checks that calling \p f throws topograsp::invalid_argument whose message starts with the
/// argument's name \p name (the library's convention for bad input).
template <class F>
void check_throws_naming(F&& f, const std::string& name) {
  try {
    f();
  } catch (const topograsp::invalid_argument& e) {
    INFO(e.what());
    CHECK(std::string(e.what()).rfind(name, 0) == 0);
    return;
  }
  FAIL("no topograsp::invalid_argument for " << name);
}

}  // namespace topograsp::test
