// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Internals of the SVG and HTML writers: fixed number formatting, XML escaping, file output.
#pragma once

#include <cstdio>
#include <fstream>
#include <string>
#include <string_view>

#include <topograsp/core/error.hpp>

namespace topograsp {

namespace detail {

/// \p v with \p digits decimals ("%.*f"; default 2, the coordinate format of the SVG writers),
/// never a negative zero ("-0", "-0.00"): a value that rounds to zero prints without its sign.
inline std::string svg_number(double v, int digits = 2) {
  char b[352];  // room for the largest double with up to 16 decimals
  std::snprintf(b, sizeof b, "%.*f", digits, v);
  std::string s(b);
  if (s.size() > 1 && s[0] == '-' && s.find_first_not_of("0.", 1) == std::string::npos)
    s.erase(0, 1);
  return s;
}

/// \p s with the five XML special characters escaped (for text and attribute values).
inline std::string xml_escape(std::string_view s) {
  std::string o;
  o.reserve(s.size());
  for (const char c : s) {
    switch (c) {
      case '<':
        o += "&lt;";
        break;
      case '>':
        o += "&gt;";
        break;
      case '&':
        o += "&amp;";
        break;
      case '"':
        o += "&quot;";
        break;
      case '\'':
        o += "&#39;";
        break;
      default:
        o += c;
    }
  }
  return o;
}

/// Writes \p text to the file \p path.
/// \throws topograsp::invalid_argument naming "path" if the file cannot be written.
inline void write_text_file(const std::string& path, std::string_view text) {
  std::ofstream f(path, std::ios::binary);
  if (!f) throw_invalid_argument("path", "cannot open " + path + " for writing");
  f.write(text.data(), static_cast<std::streamsize>(text.size()));
  if (!f) throw_invalid_argument("path", "cannot write " + path);
}

}  // namespace detail

}  // namespace topograsp
