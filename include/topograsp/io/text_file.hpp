// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Text output: fixed number formatting, XML escaping, and the atomic writer of every text file
/// topograsp writes (results, scenes, SVG, HTML, generated headers).
#pragma once

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>
#include <string_view>
#include <system_error>

#include <topograsp/core/error.hpp>
#include <topograsp/core/number_text.hpp>

namespace topograsp {

namespace detail {

/// \p v with \p digits decimals ("%.*f"; default 2, the coordinate format of the SVG writers),
/// never a negative zero ("-0", "-0.00"): a value that rounds to zero prints without its sign.
inline std::string svg_number(double v, int digits = 2) {
  char format[16];
  std::snprintf(format, sizeof format, "%%.%df", digits);
  return number_text(v, format);
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

// A name part unique to this process and call: a per-process random token and a counter.
inline std::string temporary_file_token() {
  static const std::uint64_t process = [] {
    try {
      std::random_device rd;
      return (static_cast<std::uint64_t>(rd()) << 32) ^ static_cast<std::uint64_t>(rd());
    } catch (...) {  // no entropy source: the clock
      return static_cast<std::uint64_t>(
          std::chrono::steady_clock::now().time_since_epoch().count());
    }
  }();
  static std::atomic<std::uint64_t> counter{0};
  char b[48];
  std::snprintf(b, sizeof b, "%016llx-%llu", static_cast<unsigned long long>(process),
                static_cast<unsigned long long>(counter++));
  return b;
}

/// Writes \p text to the file \p path atomically: into a temporary file in the same folder
/// (".<name>.tmp-<token>"), renamed onto \p path once it is complete. Readers see the previous
/// file or the new one, never a part; a process killed while writing leaves at most the
/// temporary file. The one function every text output of topograsp (results.json, scenes, SVG,
/// HTML) is written with.
/// \throws topograsp::invalid_argument naming "path", with the file and the system's reason, if
/// the file cannot be written (no such folder, the parent is a file, a full disk, a file-size
/// limit, \p path is a folder, ...); the temporary file is removed then and a previous file at
/// \p path is left as it was.
inline void write_text_file(const std::filesystem::path& path, std::string_view text) {
  namespace fs = std::filesystem;
  // Built by appending: GCC 12 reports a false -Wrestrict for "literal" + std::string&& at -O2.
  std::string shown(1, '"');
  shown += path.string();
  shown += '"';
  if (!path.has_filename()) throw_invalid_argument("path", shown + " names no file");
  std::string temp_name(1, '.');
  temp_name += path.filename().string();
  temp_name += ".tmp-";
  temp_name += temporary_file_token();
  const fs::path temp = path.parent_path() / temp_name;
  const auto fail = [&](std::string_view what, int error) {
    std::error_code ignored;
    fs::remove(temp, ignored);
    throw_invalid_argument("path", std::string(what) + " " + shown + " (" +
                                       std::error_code(error, std::generic_category()).message() +
                                       "); a previous file there is unchanged");
  };
  std::FILE* f = std::fopen(temp.string().c_str(), "wb");
  if (f == nullptr) return fail("cannot create a temporary file to write", errno);
  int error = 0;
  if (std::fwrite(text.data(), 1, text.size(), f) != text.size()) error = errno != 0 ? errno : EIO;
  if (std::fclose(f) != 0 && error == 0) error = errno != 0 ? errno : EIO;
  if (error != 0) fail("cannot write", error);
  std::error_code ec;
  fs::rename(temp, path, ec);
  if (ec) return fail("cannot put the written file in place as", ec.value());
}

}  // namespace detail

}  // namespace topograsp
