// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// WindingTask: the windings of chosen hand curves around a point, with the Jacobian with respect
/// to the joints.
#pragma once

#include <array>
#include <string>

#include <topograsp/core/error.hpp>
#include <topograsp/kinematics/forward.hpp>
#include <topograsp/task/detail/point_gradient.hpp>
#include <topograsp/task/hand_curve.hpp>
#include <topograsp/task/winding.hpp>

namespace topograsp {

/// The task variable phi_k(q) = w(gamma_{c_k}(q), p), k = 0..K-1: the windings (winding()) of K
/// chosen hand curves (hand_curves()) of the hand \p M around the world point p, e.g. the object's
/// centre of mass.
///
/// Jacobian: the vertex gradients of winding_gradient() chained through the point Jacobians,
/// J_k = sum_j (d w_k / d X_j)' (d X_j / d q). Exact wherever w is differentiable (see
/// winding_gradient() for the degenerate cases).
///
/// \tparam M a hand model (a reference to a constexpr Model with fingers), e.g. models::schunk_sdh
///           or models::schunk_arm_sdh
/// \tparam K how many curves (default: all of them)
template <const auto& M, int K = hand_curve_count<M>>
  requires HandModel<decltype(M)>
class WindingTask {
 public:
  using Kinematics = KinematicsData<M>;
  static constexpr int dim = K;
  static constexpr int nq = Kinematics::nq;
  static_assert(K >= 1, "a winding task needs at least one curve");

  /// The windings of curves \p curves (indices into hand_curves<M>(), repeats allowed) around
  /// \p point (world frame, m).
  /// \throws topograsp::invalid_argument naming "curves" for an index out of range, "point" for a
  ///         non-finite point.
  WindingTask(const std::array<int, K>& curves, const Vec3& point) : curves_(curves) {
    for (int c : curves_)
      if (c < 0 || c >= hand_curve_count<M>)
        detail::throw_invalid_argument("curves", "expected curve indices in [0, " +
                                                     std::to_string(hand_curve_count<M>) +
                                                     "), got " + std::to_string(c));
    set_point(point);
  }

  /// The windings of all curves, in order, around \p point.
  explicit WindingTask(const Vec3& point)
    requires(K == hand_curve_count<M>)
      : WindingTask(all_curves(), point) {}

  /// Moves the reference point (world frame, m).
  /// \throws topograsp::invalid_argument naming "point" if it is not finite.
  void set_point(const Vec3& point) {
    require_finite(point, "point");
    point_ = point;
  }
  [[nodiscard]] const Vec3& point() const noexcept { return point_; }
  [[nodiscard]] const std::array<int, K>& curves() const noexcept { return curves_; }

  /// phi(q): the K windings. Requires forward_kinematics(d, q) first.
  [[nodiscard]] Vec<K> value(const Kinematics& d) const noexcept {
    Vec<K> phi;
    std::array<Vec3, cap> x;
    for (int k = 0; k < K; ++k) {
      const int n = hand_curve_points(d, curves_[static_cast<std::size_t>(k)], x);
      phi[k] = detail::winding_unchecked(x.data(), static_cast<std::size_t>(n), point_);
    }
    return phi;
  }

  /// phi(q) and its Jacobian d phi / d q (K x nq). Requires forward_kinematics(d, q) first.
  void evaluate(const Kinematics& d, Vec<K>& phi, Mat<K, nq>& J) const noexcept {
    J.setZero();
    std::array<Vec3, cap> x, g;
    for (int k = 0; k < K; ++k) {
      const auto& curve =
          hand_curves_of<M>[static_cast<std::size_t>(curves_[static_cast<std::size_t>(k)])];
      const int n = hand_curve_points(d, curves_[static_cast<std::size_t>(k)], x);
      phi[k] = detail::winding_gradient_unchecked(x.data(), static_cast<std::size_t>(n), point_,
                                                  g.data());
      for (int j = 0; j < n; ++j) {
        const auto u = static_cast<std::size_t>(j);
        detail::add_point_gradient(d, curve.points[u].link, x[u], g[u], J.row(k));
      }
    }
  }

 private:
  static constexpr auto cap = static_cast<std::size_t>(hand_curve_capacity<M>);
  static std::array<int, K> all_curves() noexcept {
    std::array<int, K> c{};
    for (int k = 0; k < K; ++k) c[static_cast<std::size_t>(k)] = k;
    return c;
  }
  std::array<int, K> curves_{};
  Vec3 point_ = Vec3::Zero();
};

}  // namespace topograsp
