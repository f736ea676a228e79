// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// WritheTask: the writhe matrix between a chain of points on the robot and a fixed polyline, as
/// a task variable (Ho and Komura 2009; Zarubin et al. 2012).
#pragma once

#include <array>

#include <topograsp/core/error.hpp>
#include <topograsp/kinematics/forward.hpp>
#include <topograsp/task/detail/point_gradient.hpp>
#include <topograsp/task/linking.hpp>

namespace topograsp {

/// phi_{(N_B-1) i + j}(q) = segment_linking(X_i, X_{i+1}, Y_j, Y_{j+1}) (dim (NA-1)(NB-1)): the
/// writhe matrix, row by row, between the robot polyline X through \p NA link points of \p M
/// (for example a hand curve, hand_curve_chain()) and a fixed world polyline Y of \p NB points
/// (an object's edge, a handle's axis). Its entries sum to the total writhe. Jacobian: the
/// closed-form gradients of segment_linking() with respect to X_i, X_{i+1}, chained through the
/// point Jacobians. Exact wherever the segments do not meet.
template <const auto& M, std::size_t NA, std::size_t NB>
class WritheTask {
  static_assert(NA >= 2 && NB >= 2, "both polylines need at least one segment");

 public:
  using Kinematics = KinematicsData<M>;
  static constexpr int dim = static_cast<int>((NA - 1) * (NB - 1));
  static constexpr int nq = Kinematics::nq;

  /// The writhe matrix of the robot chain \p chain against the world polyline \p curve (m).
  /// \throws topograsp::invalid_argument naming "chain" (a link index out of range) or "curve"
  ///         (a non-finite point).
  WritheTask(const std::array<LinkPoint, NA>& chain, const std::array<Vec3, NB>& curve)
      : chain_(chain) {
    for (const LinkPoint& p : chain_)
      if (p.link < 0 || p.link >= static_cast<int>(M.links.size()))
        detail::throw_invalid_argument("chain", "a point names no link of the model");
    set_curve(curve);
  }

  /// Replaces the world polyline.
  /// \throws topograsp::invalid_argument naming "curve" for a non-finite point.
  void set_curve(const std::array<Vec3, NB>& curve) {
    for (const Vec3& y : curve) require_finite(y, "curve");
    curve_ = curve;
  }
  [[nodiscard]] const std::array<Vec3, NB>& curve() const noexcept { return curve_; }

  /// phi(q). Requires forward_kinematics(d, q) first.
  [[nodiscard]] Vec<dim> value(const Kinematics& d) const noexcept {
    const std::array<Vec3, NA> x = points(d);
    Vec<dim> phi;
    for (std::size_t i = 0; i + 1 < NA; ++i)
      for (std::size_t j = 0; j + 1 < NB; ++j)
        phi[static_cast<Eigen::Index>(i * (NB - 1) + j)] =
            segment_linking(x[i], x[i + 1], curve_[j], curve_[j + 1]);
    return phi;
  }

  /// phi(q) and its Jacobian (dim x nq). Requires forward_kinematics(d, q) first.
  void evaluate(const Kinematics& d, Vec<dim>& phi, Mat<dim, nq>& J) const noexcept {
    const std::array<Vec3, NA> x = points(d);
    J.setZero();
    std::array<Vec3, 4> g;
    for (std::size_t i = 0; i + 1 < NA; ++i)
      for (std::size_t j = 0; j + 1 < NB; ++j) {
        const auto r = static_cast<Eigen::Index>(i * (NB - 1) + j);
        phi[r] = segment_linking(x[i], x[i + 1], curve_[j], curve_[j + 1], &g);
        detail::add_point_gradient(d, chain_[i].link, x[i], g[0], J.row(r));
        detail::add_point_gradient(d, chain_[i + 1].link, x[i + 1], g[1], J.row(r));
      }
  }

 private:
  [[nodiscard]] std::array<Vec3, NA> points(const Kinematics& d) const noexcept {
    std::array<Vec3, NA> x;
    for (std::size_t i = 0; i < NA; ++i) x[i] = world_point(d, chain_[i]);
    return x;
  }

  std::array<LinkPoint, NA> chain_{};
  std::array<Vec3, NB> curve_{};
};

}  // namespace topograsp
