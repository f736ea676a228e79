// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Run-time lookup of a model's frame by name, with the error a task constructor throws.
#pragma once

#include <string>
#include <string_view>

#include <topograsp/core/error.hpp>

namespace topograsp::detail {

/// The index of frame \p name of \p M; throws topograsp::invalid_argument naming "frame".
template <const auto& M>
int require_frame(std::string_view name) {
  const int f = M.find_frame(name);
  if (f < 0)
    throw_invalid_argument("frame", "no frame named \"" + std::string(name) + "\" in model " +
                                        std::string(M.name.view()));
  return f;
}

/// Throws topograsp::invalid_argument naming "frame" unless 0 <= \p f < number of frames.
template <const auto& M>
void require_frame_index(int f) {
  if (f < 0 || f >= static_cast<int>(M.frames.size()))
    throw_invalid_argument("frame", "expected a frame index in [0, " +
                                        std::to_string(M.frames.size()) + "), got " +
                                        std::to_string(f));
}

}  // namespace topograsp::detail
