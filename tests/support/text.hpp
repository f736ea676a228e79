// SPDX-License-Identifier: BSD-3-Clause
// Text helpers for the tests of the writers (SVG, HTML, JSON).
#pragma once

#include <cstddef>
#include <string>

namespace topograsp::test {

/// The number of (possibly overlapping) occurrences of \p what in \p s.
inline std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = s.find(what); at != std::string::npos; at = s.find(what, at + 1)) ++n;
  return n;
}

}  // namespace topograsp::test
