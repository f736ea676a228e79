// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Internals of the SVG and HTML writers: fixed number formatting, XML escaping, file output.
#pragma once

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <string_view>

#include <topograsp/core/error.hpp>

namespace topograsp {

namespace detail {

/// \p v with two decimals ("%.2f"), never "-0.00": the coordinate format of the SVG writers.
inline std::string svg_number(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.2f", v);
  std::string s(b);
  if (s == "-0.00") s = "0.00";
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
