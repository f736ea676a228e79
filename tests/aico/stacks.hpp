// SPDX-License-Identifier: BSD-3-Clause
// Small TaskStack models for the AICO tests: a linear map C q and a frame-position reaching task.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include <topograsp/kinematics.hpp>
#include <topograsp/task/concepts.hpp>

namespace topograsp::test {

/// phi(q) = C q with target y_t and precision rho_t (rho_end at t = T, rho_mid before).
template <const auto& M, int D>
struct LinearStack {
  using Kinematics = KinematicsData<M>;
  static constexpr int dim = D;
  static constexpr std::array<int, 1> task_dims{D};
  Mat<D, M.nq> C = Mat<D, M.nq>::Zero();
  std::vector<Vec<D>> targets;  // T + 1 of them
  double rho_mid = 1.0, rho_end = 100.0;

  void residual(const Kinematics& d, int t, int T, Vec<D>& e, Mat<D, M.nq>& J) const noexcept {
    const double s = std::sqrt(t == T ? rho_end : rho_mid);
    J = s * C;
    e = s * (C * d.q - targets[static_cast<std::size_t>(t)]);
  }
};

/// The position of frame F should reach `target` at t = T (precision rho_end), with a weak
/// pull (rho_mid) along the way; a joint-space posture term keeps the problem well posed.
template <const auto& M, int F>
struct ReachStack {
  using Kinematics = KinematicsData<M>;
  static constexpr int dim = 3 + M.nq;
  static constexpr std::array<int, 2> task_dims{3, M.nq};
  Vec3 target = Vec3::Zero();
  Vec<M.nq> posture = Vec<M.nq>::Zero();
  double rho_mid = 1.0, rho_end = 1e4, rho_posture = 1e-3;
  // When set, the residual turns NaN once joint 0 exceeds this value (for the failure test).
  double nan_above = std::numeric_limits<double>::infinity();

  void residual(const Kinematics& d, int t, int T, Vec<dim>& e, Mat<dim, M.nq>& J) const noexcept {
    const double s = std::sqrt(t == T ? rho_end : rho_mid);
    const double sp = std::sqrt(rho_posture);
    e.template head<3>() = s * (d.frame_p[static_cast<std::size_t>(F)] - target);
    J.template topRows<3>() = s * frame_position_jacobian(d, F);
    e.template tail<M.nq>() = sp * (d.q - posture);
    J.template bottomRows<M.nq>() = sp * Mat<M.nq, M.nq>::Identity();
    if (d.q[0] > nan_above) e[0] = std::numeric_limits<double>::quiet_NaN();
  }
};

}  // namespace topograsp::test
