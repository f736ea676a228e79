// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// AicoMode: which state AICO plans over.
#pragma once

#include <string_view>

namespace topograsp {

/// Which state AICO plans over (aico.md, "Model").
enum class AicoMode {
  /// The state is x = (q, qdot) (2 nq) with the pseudo-dynamics x' = A x + B u + noise,
  /// A = [[I, tau I], [0, I]], B = [[tau^2/2 I], [tau I]]: the paper's mode.
  dynamic,
  /// The state is x = q (nq) with the random-walk prior x' = x + noise of covariance H^-1.
  kinematic,
};

/// "dynamic" or "kinematic".
[[nodiscard]] constexpr std::string_view to_string(AicoMode m) noexcept {
  return m == AicoMode::dynamic ? "dynamic" : "kinematic";
}

}  // namespace topograsp
