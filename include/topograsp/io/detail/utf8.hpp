// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// UTF-8 encoding of a code point, for the JSON and XML readers' character references.
#pragma once

#include <string>

namespace topograsp::detail {

/// Appends the code point \p cp (<= 0x10FFFF, not a surrogate) to \p s as UTF-8.
inline void append_utf8(std::string& s, unsigned cp) {
  if (cp < 0x80u) {
    s += static_cast<char>(cp);
  } else if (cp < 0x800u) {
    s += static_cast<char>(0xC0u | (cp >> 6));
    s += static_cast<char>(0x80u | (cp & 0x3Fu));
  } else if (cp < 0x10000u) {
    s += static_cast<char>(0xE0u | (cp >> 12));
    s += static_cast<char>(0x80u | ((cp >> 6) & 0x3Fu));
    s += static_cast<char>(0x80u | (cp & 0x3Fu));
  } else {
    s += static_cast<char>(0xF0u | (cp >> 18));
    s += static_cast<char>(0x80u | ((cp >> 12) & 0x3Fu));
    s += static_cast<char>(0x80u | ((cp >> 6) & 0x3Fu));
    s += static_cast<char>(0x80u | (cp & 0x3Fu));
  }
}

}  // namespace topograsp::detail
