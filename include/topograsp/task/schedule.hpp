// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Time schedules of a task's target and precision over a horizon of T steps, and Scheduled, a
/// task with both.
#pragma once

#include <cmath>
#include <utility>

#include <topograsp/core/error.hpp>
#include <topograsp/task/concepts.hpp>

namespace topograsp {

/// The target y*(t) of a task of dimension \p N at step t of 0..T: constant (the goal at every
/// step) or interpolated linearly from a start value at t = 0 to the goal at t = T.
template <int N>
struct TargetSchedule {
  Vec<N> start = Vec<N>::Zero();  ///< y*(0) when interpolating
  Vec<N> goal = Vec<N>::Zero();   ///< y*(T), and y*(t) for every t when constant
  bool interpolate = false;

  /// y*(t); t >= T (or T <= 0) gives the goal.
  [[nodiscard]] Vec<N> at(int t, int T) const noexcept {
    if (!interpolate || T <= 0 || t >= T) return goal;
    if (t <= 0) return start;
    const double s = static_cast<double>(t) / static_cast<double>(T);
    return start + s * (goal - start);
  }
};

/// A constant target \p y.
/// \throws topograsp::invalid_argument naming "target" if an entry is not finite.
template <int N>
[[nodiscard]] TargetSchedule<N> constant_target(const Vec<N>& y) {
  require_finite(y, "target");
  return {y, y, false};
}

/// A target moving linearly from \p start at t = 0 to \p goal at t = T. A TaskSet can set the
/// start to the task's value at the initial configuration (TaskSet::start_from()).
/// \throws topograsp::invalid_argument naming "start" or "goal".
template <int N>
[[nodiscard]] TargetSchedule<N> interpolated_target(const Vec<N>& start, const Vec<N>& goal) {
  require_finite(start, "start");
  require_finite(goal, "goal");
  return {start, goal, true};
}

/// The precision rho(t) of a task: \c mid for t < T and \c end at t = T (the usual AICO schedule:
/// a weak pull on the way, a strong one at the end). Both >= 0; 0 switches the task off.
struct PrecisionSchedule {
  double mid = 0.0;
  double end = 0.0;
  /// rho(t).
  [[nodiscard]] double at(int t, int T) const noexcept { return t >= T ? end : mid; }
};

/// The same precision \p rho at every step.
/// \throws topograsp::invalid_argument naming "precision" unless 0 <= rho < infinity.
[[nodiscard]] inline PrecisionSchedule constant_precision(double rho) {
  require_non_negative(rho, "precision");
  return {rho, rho};
}

/// Precision \p mid on the way and \p end at the final step.
/// \throws topograsp::invalid_argument naming "precision" unless both are finite and >= 0.
[[nodiscard]] inline PrecisionSchedule precision(double mid, double end) {
  const PrecisionSchedule a = constant_precision(mid), b = constant_precision(end);
  return {a.mid, b.end};
}

/// A task variable with its target and precision schedules: one entry of a TaskSet.
template <TaskVariable Task>
struct Scheduled {
  Task task;
  TargetSchedule<Task::dim> target;
  PrecisionSchedule precision;
};

/// Bundles \p task with a target and a precision schedule for a TaskSet.
template <TaskVariable Task>
[[nodiscard]] Scheduled<Task> scheduled(Task task, const TargetSchedule<Task::dim>& target,
                                        const PrecisionSchedule& precision) {
  return {std::move(task), target, precision};
}

}  // namespace topograsp
