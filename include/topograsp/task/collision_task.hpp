// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// CollisionTask: the collision potential between a model's link shapes and an object, with its
/// exact Jacobian.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/geometry/composite.hpp>
#include <topograsp/geometry/model_shapes.hpp>
#include <topograsp/geometry/signed_distance.hpp>
#include <topograsp/kinematics/data.hpp>
#include <topograsp/task/detail/point_gradient.hpp>

namespace topograsp {

/// The collision potential of the link shapes of \p M against a static object (dim 1):
///
/// \f[ \phi(q) = \sum_{s, o:\, d_{so}(q) < m} \left(1 - \frac{d_{so}(q)}{m}\right)^2 \f]
///
/// over the active link shapes s and the object's parts o, with d_so their signed distance
/// (signed_distance()) and m > 0 the margin. phi is 0 when every shape is at least m away, rises
/// from 0 with zero slope at d = m (so it is C1 there), is 1 per pair at contact and keeps growing
/// (quadratically, without bound) as the penetration deepens. The usual target is 0.
///
/// Jacobian: with n the unit normal from the link shape toward the part and p_s the witness point
/// on the link shape, d d_so / d q = -n' J_p(p_s) (the object does not move; J_p is the point
/// Jacobian of p_s attached to the shape's link), so
/// \f[ \frac{\partial\phi}{\partial q} = \sum \frac{2}{m}\left(1 - \frac{d_{so}}{m}\right)
///     n' J_p(p_s). \f]
/// It is exact wherever the distance is differentiable (the closest features are unique).
template <const auto& M>
class CollisionTask {
 public:
  using Kinematics = KinematicsData<M>;
  static constexpr int dim = 1;
  static constexpr int nq = Kinematics::nq;
  static constexpr std::size_t n_shapes = std::remove_cvref_t<decltype(M)>::n_shapes;

  /// The potential of every link shape of \p M against \p object (world frame) with margin
  /// \p margin (m).
  /// \throws topograsp::invalid_argument naming "margin" unless it is finite and > 0.
  CollisionTask(Composite object, double margin) : object_(std::move(object)) {
    require_positive(margin, "margin");
    margin_ = margin;
    active_.fill(true);
    radii_.reserve(object_.size());
    for (const Primitive& s : object_.parts()) radii_.push_back(s.bounding_radius());
  }

  /// Chooses which link shapes count (by index in M.shapes), e.g. to leave out the arm.
  void set_active(const std::array<bool, n_shapes>& active) noexcept { active_ = active; }
  [[nodiscard]] const std::array<bool, n_shapes>& active() const noexcept { return active_; }
  [[nodiscard]] double margin() const noexcept { return margin_; }
  [[nodiscard]] const Composite& object() const noexcept { return object_; }

  /// phi(q). Requires forward_kinematics(d, q) first.
  [[nodiscard]] Vec<1> value(const Kinematics& d) const noexcept {
    double phi = 0.0;
    for_each_close_pair(d, [&](std::size_t, const Contact& c) {
      const double u = 1.0 - c.distance / margin_;
      phi += u * u;
    });
    return Vec<1>(phi);
  }

  /// phi(q) and d phi / d q (1 x nq). Requires forward_kinematics(d, q) first.
  void evaluate(const Kinematics& d, Vec<1>& phi, Mat<1, nq>& J) const noexcept {
    J.setZero();
    double sum = 0.0;
    for_each_close_pair(d, [&](std::size_t shape, const Contact& c) {
      const double u = 1.0 - c.distance / margin_;
      sum += u * u;
      // d phi = -2 u / m dd, dd = -n . v(p_a): the gradient with respect to p_a is 2 u / m n.
      detail::add_point_gradient(d, M.shapes[shape].link, c.point_a,
                                 Vec3((2.0 * u / margin_) * c.normal), J.row(0));
    });
    phi[0] = sum;
  }

  /// The smallest signed distance between an active link shape and the object (m); +infinity if
  /// there is none. Requires forward_kinematics(d, q) first.
  [[nodiscard]] double min_distance(const Kinematics& d) const noexcept {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < n_shapes; ++i) {
      if (!active_[i]) continue;
      const Primitive s = world_shape(d, i);
      for (const Primitive& o : object_.parts())
        best = std::min(best, signed_distance(s, o).distance);
    }
    return best;
  }

 private:
  // Calls f(shape index, contact) for every active shape and part closer than the margin;
  // bounding spheres skip the pairs that cannot be.
  template <class F>
  void for_each_close_pair(const Kinematics& d, F&& f) const noexcept {
    const auto parts = object_.parts();
    for (std::size_t i = 0; i < n_shapes; ++i) {
      if (!active_[i]) continue;
      const Primitive s = world_shape(d, i);
      const double rs = s.bounding_radius();
      for (std::size_t k = 0; k < parts.size(); ++k) {
        if ((s.p - parts[k].p).norm() - rs - radii_[k] >= margin_) continue;
        const Contact c = signed_distance(s, parts[k]);
        if (c.distance < margin_) f(i, c);
      }
    }
  }

  Composite object_;
  std::vector<double> radii_;
  double margin_ = 0.0;
  std::array<bool, n_shapes> active_{};
};

}  // namespace topograsp
