// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// AicoProblem: an immutable AICO planning problem (model, tasks, start, options).
#pragma once

#include <cmath>
#include <cstdio>
#include <string>
#include <type_traits>
#include <utility>

#include <topograsp/aico/detail/transition.hpp>
#include <topograsp/aico/options.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/kinematics/data.hpp>
#include <topograsp/task/concepts.hpp>

namespace topograsp {

/// An AICO planning problem: the robot \p M, the tasks \p Stack, the fixed start state and the
/// options, checked once at construction and immutable afterwards.
///
/// \tparam M a constexpr model (models::schunk_arm_sdh, ...).
/// \tparam Stack a TaskStack over KinematicsData<M>: the whitened residual of all tasks at a step.
/// \tparam Mode AicoMode::dynamic (state (q, qdot), the paper's) or AicoMode::kinematic (state q).
template <const auto& M, TaskStack Stack, AicoMode Mode = AicoMode::dynamic>
class AicoProblem {
  static_assert(std::is_same_v<typename Stack::Kinematics, KinematicsData<M>>,
                "the task stack must be written for KinematicsData<M>");

 public:
  using StackType = Stack;
  using Kinematics = KinematicsData<M>;
  using Transition = detail::Transition<M.nq, Mode>;
  static constexpr AicoMode mode = Mode;
  static constexpr int nq = M.nq;              ///< joints
  static constexpr int nx = Transition::nx;    ///< state dimension (2 nq or nq)
  static constexpr int task_dim = Stack::dim;  ///< rows of the stacked task residual
  using Config = Vec<nq>;
  using State = Vec<nx>;

  /// A problem that starts at rest at \p q_start (dim nq, rad).
  /// \throws topograsp::invalid_argument naming "q_start" or "options.<field>" for a wrongly
  /// sized or non-finite start or an out-of-range option (steps < 1, a non-positive precision...).
  template <EigenDense D>
  AicoProblem(Stack stack, const D& q_start, const AicoOptions& options = {})
      : AicoProblem(std::move(stack), q_start, Config::Zero(), options) {}

  /// A problem that starts at \p q_start (dim nq, rad) with joint velocity \p qdot_start
  /// (dim nq, rad/s; ignored in kinematic mode).
  /// \throws topograsp::invalid_argument as the other constructor, or naming "qdot_start".
  template <EigenDense D, EigenDense E>
  AicoProblem(Stack stack, const D& q_start, const E& qdot_start, const AicoOptions& options)
      : stack_(std::move(stack)), options_(options) {
    require_configuration<M>(q_start, "q_start");
    require_size(qdot_start, nq, "qdot_start");
    require_finite(qdot_start, "qdot_start");
    check_options(options);
    q_start_ = q_start;
    if constexpr (Mode == AicoMode::dynamic) {
      x_start_ << q_start_, qdot_start;
    } else {
      x_start_ = q_start_;
    }
    transition_ = Transition::make(step_length(), options.control_precision, options.process_noise);
  }

  [[nodiscard]] const Stack& stack() const noexcept { return stack_; }
  [[nodiscard]] const AicoOptions& options() const noexcept { return options_; }
  [[nodiscard]] const Config& q_start() const noexcept { return q_start_; }
  /// The fixed start state x_0 (dim nx).
  [[nodiscard]] const State& x_start() const noexcept { return x_start_; }
  /// The number of time steps T.
  [[nodiscard]] int steps() const noexcept { return options_.steps; }
  /// The step length tau = duration / T (s).
  [[nodiscard]] double step_length() const noexcept {
    return options_.duration / static_cast<double>(options_.steps);
  }
  /// The transition prior's constants (internal).
  [[nodiscard]] const Transition& transition() const noexcept { return transition_; }

 private:
  static void check_options(const AicoOptions& o) {
    if (o.steps < 1 || o.steps > k_max_aico_steps)
      detail::throw_invalid_argument("options.steps", "expected 1 to " +
                                                          std::to_string(k_max_aico_steps) +
                                                          " steps, got " + std::to_string(o.steps));
    require_positive(o.duration, "options.duration");
    require_at_most(o.duration, 1e6, "options.duration");
    if (!(o.duration >= 1e-6))
      detail::throw_invalid_argument("options.duration",
                                     "expected at least 1e-6 s, got " + std::to_string(o.duration));
    require_positive(o.control_precision, "options.control_precision");
    require_at_most(o.control_precision, 1e100, "options.control_precision");
    if constexpr (Mode == AicoMode::dynamic) {
      require_positive(o.process_noise, "options.process_noise");
      require_at_most(o.process_noise, 1e100, "options.process_noise");
    }
    require_non_negative(o.damping, "options.damping");
    require_at_most(o.damping, 1e100, "options.damping");
    if (!(o.damping_increase > 1.0) || !std::isfinite(o.damping_increase))
      detail::throw_invalid_argument("options.damping_increase", "expected a finite number > 1");
    if (!(o.damping_decrease >= 1.0) || !std::isfinite(o.damping_decrease))
      detail::throw_invalid_argument("options.damping_decrease", "expected a finite number >= 1");
    require_positive(o.tolerance, "options.tolerance");
    require_positive(o.max_step, "options.max_step");
    require_non_negative(o.cost_tolerance, "options.cost_tolerance");
    require_at_most(o.damping_increase, 1e10, "options.damping_increase");
    require_at_most(o.damping_decrease, 1e10, "options.damping_decrease");
    if (o.max_sweeps < 1 || o.max_sweeps > 1000000)
      detail::throw_invalid_argument("options.max_sweeps", "expected 1 to 1000000");
    if (o.max_rejections < 1 || o.max_rejections > 1000000)
      detail::throw_invalid_argument("options.max_rejections", "expected 1 to 1000000");
    if (o.local_iterations < 1 || o.local_iterations > 1000)
      detail::throw_invalid_argument("options.local_iterations", "expected 1 to 1000");
    require_non_negative(o.terminal_precision, "options.terminal_precision");
    require_at_most(o.terminal_precision, 1e100, "options.terminal_precision");
  }
  static void require_at_most(double value, double bound, std::string_view argument) {
    if (!(value <= bound)) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "expected at most %g, got %g", bound, value);
      detail::throw_invalid_argument(argument, buf);
    }
  }

  Stack stack_;
  AicoOptions options_;
  Config q_start_ = Config::Zero();
  State x_start_ = State::Zero();
  Transition transition_{};
};

}  // namespace topograsp
