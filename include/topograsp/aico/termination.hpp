// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// AicoTermination: why an AICO solve stopped.
#pragma once

#include <string_view>

#include <topograsp/core/status.hpp>

namespace topograsp {

/// Why an AICO solve stopped.
enum class AicoTermination {
  step_tolerance,  ///< an accepted sweep moved no configuration by tolerance or more
  cost_tolerance,  ///< an accepted sweep lowered the cost by less than cost_tolerance (relative)
  max_sweeps,      ///< max_sweeps sweeps were run
  max_rejections,  ///< max_rejections sweeps in a row raised the cost
  non_finite,      ///< a task value, Jacobian or cost turned non-finite
  factorisation,   ///< a belief or message matrix was not positive definite even when damped
};

/// A short lower-case name for \p t ("step_tolerance", ...).
[[nodiscard]] constexpr std::string_view to_string(AicoTermination t) noexcept {
  switch (t) {
    case AicoTermination::step_tolerance:
      return "step_tolerance";
    case AicoTermination::cost_tolerance:
      return "cost_tolerance";
    case AicoTermination::max_sweeps:
      return "max_sweeps";
    case AicoTermination::max_rejections:
      return "max_rejections";
    case AicoTermination::non_finite:
      return "non_finite";
    case AicoTermination::factorisation:
      return "factorisation";
  }
  return "unknown";
}

/// The Status a termination reason maps to: success for the two tolerances, no_convergence when
/// a budget ran out, numerical_issue for non-finite values or failed factorisations.
[[nodiscard]] constexpr Status status_of(AicoTermination t) noexcept {
  switch (t) {
    case AicoTermination::step_tolerance:
    case AicoTermination::cost_tolerance:
      return Status::success;
    case AicoTermination::max_sweeps:
    case AicoTermination::max_rejections:
      return Status::no_convergence;
    case AicoTermination::non_finite:
    case AicoTermination::factorisation:
      return Status::numerical_issue;
  }
  return Status::numerical_issue;
}

}  // namespace topograsp
