// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Primitive: a convex collision shape (sphere, capsule, box, cylinder) placed in the world, the
/// run-time counterpart of a model's ShapeSpec. BasicPrimitive<S> is the same shape over the
/// scalar type S; the physics module's ShapeView<S> is one with a polytope attached.
#pragma once

#include <cmath>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/geometry/detail/closest.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp {

namespace detail {

/// The radius of the smallest sphere about a shape's centre that holds the shape of \p type and
/// \p size (ShapeSpec::size): a sphere's radius, a capsule's radius plus half length, a box's
/// half diagonal, a cylinder's sqrt(r^2 + l^2).
template <class S>
[[nodiscard]] S bounding_radius(ShapeType type, const Vec<3, S>& size) noexcept {
  switch (type) {
    case ShapeType::sphere:
      return size[0];
    case ShapeType::capsule:
      return size[0] + size[1];
    case ShapeType::box:
      return size.norm();
    case ShapeType::cylinder:
      return std::sqrt(size[0] * size[0] + size[1] * size[1]);
  }
  return size.norm();
}

}  // namespace detail

/// A convex shape with a world pose. Every shape is centred at \c p; capsules and cylinders run
/// along the third column of \c R (their local z axis).
///
/// - sphere: size = {radius, -, -}
/// - capsule: size = {radius, half length of the segment, -}
/// - box: size = half extents {x, y, z} along the columns of R
/// - cylinder: size = {radius, half height, -}
///
/// \tparam S the scalar type (Primitive is BasicPrimitive<double>; the named constructors take
///         double arguments and exist for S = double only).
template <class S>
struct BasicPrimitive {
  ShapeType type = ShapeType::sphere;
  Mat<3, 3, S> R = Mat<3, 3, S>::Identity();  ///< orientation: local to world
  Vec<3, S> p = Vec<3, S>::Zero();            ///< centre (m)
  Vec<3, S> size = Vec<3, S>::Zero();         ///< see above (m)

  /// A sphere of \p radius at \p centre.
  /// \throws topograsp::invalid_argument naming "centre" or "radius".
  [[nodiscard]] static BasicPrimitive sphere(const Vec3& centre, double radius) {
    require_finite(centre, "centre");
    require_positive(radius, "radius");
    BasicPrimitive s;
    s.type = ShapeType::sphere;
    s.p = centre;
    s.size = Vec3(radius, 0.0, 0.0);
    return s;
  }

  /// A capsule of \p radius around the segment from \p a to \p b (a = b gives a sphere-like
  /// capsule of zero length).
  /// \throws topograsp::invalid_argument naming "a", "b" or "radius".
  [[nodiscard]] static BasicPrimitive capsule(const Vec3& a, const Vec3& b, double radius) {
    require_finite(a, "a");
    require_finite(b, "b");
    require_positive(radius, "radius");
    BasicPrimitive s;
    s.type = ShapeType::capsule;
    s.p = 0.5 * (a + b);
    const Vec3 u = b - a;
    const double len = u.norm();
    if (len > 0.0) s.R = Eigen::Quaterniond::FromTwoVectors(Vec3::UnitZ(), u).toRotationMatrix();
    s.size = Vec3(radius, 0.5 * len, 0.0);
    return s;
  }

  /// A box with half extents \p half at \p pose (its rotation must be orthonormal).
  /// \throws topograsp::invalid_argument naming "pose" (non-finite) or "half" (an entry <= 0).
  [[nodiscard]] static BasicPrimitive box(const Eigen::Isometry3d& pose, const Vec3& half) {
    require_finite(pose.matrix(), "pose");
    for (int k = 0; k < 3; ++k) require_positive(half[k], "half");
    BasicPrimitive s;
    s.type = ShapeType::box;
    s.R = pose.linear();
    s.p = pose.translation();
    s.size = half;
    return s;
  }

  /// A cylinder of \p radius and height 2 * \p half_height along the z axis of \p pose.
  /// \throws topograsp::invalid_argument naming "pose", "radius" or "half_height" (< 0).
  [[nodiscard]] static BasicPrimitive cylinder(const Eigen::Isometry3d& pose, double radius,
                                               double half_height) {
    require_finite(pose.matrix(), "pose");
    require_positive(radius, "radius");
    require_non_negative(half_height, "half_height");
    BasicPrimitive s;
    s.type = ShapeType::cylinder;
    s.R = pose.linear();
    s.p = pose.translation();
    s.size = Vec3(radius, half_height, 0.0);
    return s;
  }

  /// The shape \p spec of a model (pose in its link frame) on a link at world pose (R_link,
  /// p_link). No checks (a checked model's shapes are valid).
  [[nodiscard]] static BasicPrimitive from_spec(const ShapeSpec& spec, const Mat3& R_link,
                                                const Vec3& p_link) noexcept {
    BasicPrimitive s;
    s.type = spec.type;
    s.R.noalias() = R_link * spec.pose.rotation();
    s.p.noalias() = p_link + R_link * spec.pose.translation();
    s.size = Vec<3, S>(spec.size[0], spec.size[1], spec.size[2]);
    return s;
  }

  /// The radius of the smallest sphere about \c p that holds the shape (m).
  [[nodiscard]] S bounding_radius() const noexcept {
    return detail::bounding_radius<S>(type, size);
  }

  /// The volume (m^3).
  [[nodiscard]] S volume() const noexcept {
    switch (type) {
      case ShapeType::sphere:
        return 4.0 / 3.0 * pi * size[0] * size[0] * size[0];
      case ShapeType::capsule:
        return pi * size[0] * size[0] * (2.0 * size[1] + 4.0 / 3.0 * size[0]);
      case ShapeType::box:
        return 8.0 * size[0] * size[1] * size[2];
      case ShapeType::cylinder:
        return pi * size[0] * size[0] * 2.0 * size[1];
    }
    return 0.0;
  }

  /// This shape moved by the rigid transform \p T (applied in the world frame).
  [[nodiscard]] BasicPrimitive transformed(const Eigen::Isometry3d& T) const noexcept {
    BasicPrimitive s = *this;
    s.R = T.linear() * R;
    s.p = T * p;
    return s;
  }
};

/// The shape type of the geometry module (double precision).
using Primitive = BasicPrimitive<double>;

namespace detail {

/// True for the shapes that are a core swept by a ball: a sphere (a point) and a capsule (a
/// segment).
[[nodiscard]] constexpr bool is_rounded(ShapeType t) noexcept {
  return t == ShapeType::sphere || t == ShapeType::capsule;
}

/// The core segment (a0, a1) of a sphere (a0 = a1 = its centre) or capsule (along the third
/// column of R).
template <class S>
void core_segment(const BasicPrimitive<S>& v, Vec<3, S>& a0, Vec<3, S>& a1) noexcept {
  if (v.type == ShapeType::capsule) {
    const Vec<3, S> h = v.R.col(2) * v.size[1];
    a0 = v.p - h;
    a1 = v.p + h;
  } else {
    a0 = a1 = v.p;
  }
}

}  // namespace detail

}  // namespace topograsp
