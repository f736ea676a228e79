// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// AicoResult: the outcome of an AICO solve.
#pragma once

#include <vector>

#include <topograsp/aico/sweep_record.hpp>
#include <topograsp/aico/termination.hpp>
#include <topograsp/core/eigen.hpp>
#include <topograsp/core/status.hpp>

namespace topograsp {

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
