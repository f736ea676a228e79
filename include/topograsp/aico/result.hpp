// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The outcome of an AICO solve: AicoTermination (why it stopped, and the Status that maps to),
/// AicoSweepRecord (what one sweep did) and AicoResult (the trajectory, costs and log).
#pragma once

#include <string_view>
#include <vector>

#include <topograsp/core/eigen.hpp>
#include <topograsp/core/status.hpp>

namespace topograsp {

/// Why an AICO solve stopped (docs/aico.md, "Sweeps, acceptance and termination").
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

/// What one AICO sweep did, for logs and plots.
struct AicoSweepRecord {
  double cost = 0.0;         ///< true cost of the sweep's trajectory (before acceptance)
  double damping = 0.0;      ///< damping alpha the sweep ran with
  double seconds = 0.0;      ///< wall time of the sweep including the cost evaluation (s)
  double step = 0.0;         ///< largest change of a configuration against the accepted one (rad)
  int task_evaluations = 0;  ///< task re-evaluations during the sweep
  bool accepted = false;     ///< whether the trajectory was kept
};

/// The outcome of an AICO solve for a robot with \p NQ joints. The trajectory is always the best
/// one found (never worse than the initial one) and always finite.
template <int NQ>
struct [[nodiscard]] AicoResult {
  Status status = Status::invalid_input;  ///< success, no_convergence or numerical_issue
  AicoTermination termination = AicoTermination::max_sweeps;  ///< why the solve stopped
  std::vector<Vec<NQ>> q;                                     ///< configurations q_0..q_T (rad)
  std::vector<Vec<NQ>> qdot;  ///< joint velocities (rad/s); finite differences in kinematic mode
  double cost = 0.0;          ///< objective of the returned trajectory
  double control_cost = 0.0;  ///< its transition (control) part
  std::vector<double> task_costs;    ///< its task part, one entry per task of the stack
  std::vector<double> cost_history;  ///< initial cost, then the cost after each accepted sweep
  std::vector<AicoSweepRecord> sweep_log;  ///< every sweep, accepted or not
  int sweeps = 0;                          ///< sweeps run
  int rejected = 0;                        ///< sweeps rejected
  double damping = 0.0;                    ///< damping alpha at the end

  /// The final configuration q_T (rad).
  [[nodiscard]] const Vec<NQ>& final_configuration() const { return q.back(); }
  /// True if status is Status::success.
  [[nodiscard]] bool ok() const noexcept { return status == Status::success; }
};

}  // namespace topograsp
