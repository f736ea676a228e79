// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Names (of objects, methods) made safe as a part of a file name inside an output folder.
#pragma once

#include <string>
#include <string_view>

namespace topograsp {

/// \p name as a part of a file name that cannot leave its folder nor hide: every byte other than
/// an ASCII letter, digit, '-', '_' or a '.' that is not the first becomes '_' (so "/", "\",
/// control characters and a leading dot never reach the file system), and an empty name becomes
/// "_"; only the first max_file_name_part bytes are kept (a file name has at most 255). Distinct
/// names can map to the same part ("a/b" and "a_b"); callers that need distinct files check for
/// that. Never throws but std::bad_alloc.
inline constexpr std::size_t max_file_name_part = 100;

[[nodiscard]] inline std::string file_name_part(std::string_view name) {
  if (name.empty()) return "_";
  std::string part(name.substr(0, max_file_name_part));
  for (std::size_t i = 0; i < part.size(); ++i) {
    const char c = part[i];
    const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
                      c == '-' || c == '_' || (c == '.' && i > 0);
    if (!safe) part[i] = '_';
  }
  return part;
}

}  // namespace topograsp
