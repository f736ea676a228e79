// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// PostureTask: the weighted configuration, to pull toward a comfortable posture.
#pragma once

#include <topograsp/core/error.hpp>
#include <topograsp/kinematics/data.hpp>

namespace topograsp {

/// phi(q) = W q (dim nq), W = diag(weights). With the target W q_c, the cost
/// rho |W (q - q_c)|^2 is the weighted squared distance to the comfort configuration q_c.
/// Jacobian: W.
template <const auto& M>
class PostureTask {
 public:
  using Kinematics = KinematicsData<M>;
  static constexpr int nq = Kinematics::nq;
  static constexpr int dim = nq;

  /// Unit weights.
  PostureTask() = default;
  /// Per-entry weights (dim nq, finite, >= 0), e.g. 0 for the arm and 1 for the fingers.
  /// \throws topograsp::invalid_argument naming "weights".
  explicit PostureTask(const Vec<nq>& weights) : weights_(weights) {
    require_finite(weights, "weights");
    if ((weights.array() < 0.0).any())
      detail::throw_invalid_argument("weights", "expected weights >= 0");
  }

  /// The target that makes the comfort configuration \p q_c the goal: W q_c.
  [[nodiscard]] Vec<nq> target(const Vec<nq>& q_c) const noexcept {
    return weights_.cwiseProduct(q_c);
  }

  /// phi(q). Reads d.q (forward_kinematics(d, q) stores it).
  [[nodiscard]] Vec<nq> value(const Kinematics& d) const noexcept {
    return weights_.cwiseProduct(d.q);
  }
  /// phi(q) and its Jacobian (nq x nq).
  void evaluate(const Kinematics& d, Vec<nq>& phi, Mat<nq, nq>& J) const noexcept {
    phi = value(d);
    J = weights_.asDiagonal();
  }

 private:
  Vec<nq> weights_ = Vec<nq>::Ones();
};

}  // namespace topograsp
