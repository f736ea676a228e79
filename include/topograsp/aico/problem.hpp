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
    for (const Parameter<AicoOptions>& p : aico_parameters)
      if (Mode == AicoMode::dynamic || p.name != "process_noise")
        check_parameter(p, p.get(o), "options.");
  }

  Stack stack_;
  AicoOptions options_;
  Config q_start_ = Config::Zero();
  State x_start_ = State::Zero();
  Transition transition_{};
};

}  // namespace topograsp
