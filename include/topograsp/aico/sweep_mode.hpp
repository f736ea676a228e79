// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// SweepMode: how often AICO relinearises a time step within one sweep.
#pragma once

#include <string_view>

namespace topograsp {

/// How often a sweep relocates (moves the linearisation point and re-evaluates the tasks of) a
/// time step before moving on to the next one.
enum class SweepMode {
  /// At most one relocation per step and pass (Toussaint's "symmetric" sweeps).
  symmetric,
  /// Up to AicoOptions::local_iterations relocations per step and pass, each followed by a new
  /// belief: a few local Gauss-Newton steps on the step's marginal.
  local_gauss_newton,
};

/// "symmetric" or "local_gauss_newton".
[[nodiscard]] constexpr std::string_view to_string(SweepMode m) noexcept {
  return m == SweepMode::symmetric ? "symmetric" : "local_gauss_newton";
}

}  // namespace topograsp
