// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The outcome of a numerical computation, reported in its result rather than thrown.
#pragma once

#include <string_view>

namespace topograsp {

/// How a computation ended; mirrors Eigen::ComputationInfo.
enum class Status {
  success,          ///< converged or completed as asked
  numerical_issue,  ///< a value became non-finite or a factorisation failed
  no_convergence,   ///< an iteration budget ran out before the tolerance was met
  invalid_input,    ///< the input was rejected before any work was done
};

/// A short lower-case name for \p s ("success", "numerical_issue", ...).
[[nodiscard]] constexpr std::string_view to_string(Status s) noexcept {
  switch (s) {
    case Status::success:
      return "success";
    case Status::numerical_issue:
      return "numerical_issue";
    case Status::no_convergence:
      return "no_convergence";
    case Status::invalid_input:
      return "invalid_input";
  }
  return "unknown";
}

}  // namespace topograsp
