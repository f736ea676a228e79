// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// One number as the library's messages, help texts and drawings print it.
#pragma once

#include <cstdio>
#include <string>

namespace topograsp::detail {

/// \p v as printf's \p format writes it (a format with one double conversion: "%g" by default,
/// "%.1f", "%+.0f"), never a negative zero: a value that prints as zero ("-0", "-0.00") prints
/// without its minus sign.
inline std::string number_text(double v, const char* format = "%g") {
  char b[352];  // room for the largest double with up to 16 decimals
  // NOLINTNEXTLINE(cppcoreguidelines-pro-type-vararg): the format is the caller's literal.
  std::snprintf(b, sizeof b, format, v);
  std::string s(b);
  if (s.size() > 1 && s[0] == '-' && s.find_first_not_of("0.", 1) == std::string::npos)
    s.erase(0, 1);
  return s;
}

}  // namespace topograsp::detail
