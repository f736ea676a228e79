// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The contact wrenches of a grasp, as the Ferrari-Canny epsilon (evaluation/grasp_quality.hpp)
/// and GraspIt use them: each contact's friction cone linearised into edges, each edge a unit
/// normal force plus its friction, its torque about the object's centre divided by a length.
/// Eigen only: the hull itself (qhull) is in grasp_quality.hpp. See docs/evaluation.md.
/// affine_dimension (an SVD) is a template with nothing to give, instantiated only where it is
/// called (docs/architecture.md, "Compile time").
#pragma once

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Eigenvalues>

#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/model/spec.hpp>

namespace topograsp {

/// One point contact of a grasp on an object, in world (or any common) coordinates.
struct ContactForQuality {
  Vec3 point = Vec3::Zero();    ///< the contact point (m)
  Vec3 normal = Vec3::UnitZ();  ///< pointing INTO the object (normalised when used)
  double friction = 0.0;        ///< Coulomb coefficient, >= 0 (0: a frictionless contact)
};

/// How the friction cones are linearised.
struct QualityOptions {
  /// Edges of each contact's linearised friction cone (GraspIt: 8), in [3, k_max_edges]. A
  /// frictionless contact gives one wrench whatever this is.
  int edges = 8;
  /// The largest number of edges accepted.
  static constexpr int k_max_edges = 4096;
};

/// The wrenches of \p contacts as columns (force; torque / torque_scale), appended to nothing:
/// \p out is resized to 6 x (number of wrenches). Each contact with friction mu > 0 gives
/// options.edges wrenches, the forces n + mu (cos a_k t1 + sin a_k t2) for a_k = 2 pi k / edges
/// (unit normal force on the cone's boundary, GraspIt's PointContact::setUpFrictionEdges), t1 and
/// t2 a tangent basis of n; a frictionless contact gives the one force n. The torque of a force f
/// at point p is (p - centre) x f, divided by \p torque_scale (m) so that every coordinate is a
/// force (N per N of normal force).
///
/// Throws topograsp::invalid_argument naming the argument ("contacts[2].normal", "centre",
/// "torque_scale", "options.edges") for a non-finite point, a non-finite or zero normal, a
/// negative or non-finite friction, a non-finite centre, a torque_scale that is not finite and
/// > 0, or edges outside [3, QualityOptions::k_max_edges].
inline void contact_wrenches(std::span<const ContactForQuality> contacts, const Vec3& centre,
                             double torque_scale, const QualityOptions& options,
                             Eigen::Matrix<double, 6, Eigen::Dynamic>& out) {
  require_finite(centre, "centre");
  require_positive(torque_scale, "torque_scale");
  if (options.edges < 3 || options.edges > QualityOptions::k_max_edges)
    detail::throw_invalid_argument("options.edges",
                                   "expected 3 to " + std::to_string(QualityOptions::k_max_edges) +
                                       " edges, got " + std::to_string(options.edges));
  Eigen::Index count = 0;
  for (std::size_t i = 0; i < contacts.size(); ++i) {
    const ContactForQuality& c = contacts[i];
    // The argument's name is built only for an error: this loop runs for every grasp scored.
    const auto name = [i](std::string_view field) {
      return "contacts[" + std::to_string(i) + "]." + std::string(field);
    };
    if (!c.point.allFinite()) require_finite(c.point, name("point"));
    if (!c.normal.allFinite()) require_finite(c.normal, name("normal"));
    if (!(c.normal.norm() > 0.0))
      detail::throw_invalid_argument(name("normal"), "expected a non-zero normal");
    if (!(c.friction >= 0.0) || !std::isfinite(c.friction))
      require_non_negative(c.friction, name("friction"));
    count += c.friction > 0.0 ? options.edges : 1;
  }
  out.resize(6, count);
  const double inv_scale = 1.0 / torque_scale;
  Eigen::Index col = 0;
  for (const ContactForQuality& c : contacts) {
    const Vec3 n = c.normal.normalized();
    const Vec3 r = c.point - centre;
    if (!(c.friction > 0.0)) {
      out.col(col).head<3>() = n;
      out.col(col).tail<3>() = r.cross(n) * inv_scale;
      ++col;
      continue;
    }
    // A tangent basis: t1 perpendicular to n and to the world axis least aligned with n.
    Eigen::Index least = 0;
    n.cwiseAbs().minCoeff(&least);
    const Vec3 t1 = n.cross(Vec3::Unit(least)).normalized();
    const Vec3 t2 = n.cross(t1);
    for (int k = 0; k < options.edges; ++k) {
      const double a = 2.0 * std::numbers::pi * k / options.edges;
      const Vec3 f = n + c.friction * (std::cos(a) * t1 + std::sin(a) * t2);
      out.col(col).head<3>() = f;
      out.col(col).tail<3>() = r.cross(f) * inv_scale;
      ++col;
    }
  }
}

/// The affine dimension (0 to 6) of the points \p w (columns): the number of singular values of
/// the centred points above \p relative_tolerance times the largest. 0 for fewer than 2 points.
template <class = void>
[[nodiscard]] int affine_dimension(const Eigen::Matrix<double, 6, Eigen::Dynamic>& w,
                                   double relative_tolerance = 1e-7) {
  if (w.cols() < 2) return 0;
  const Vec<6> mean = w.rowwise().mean();
  const Eigen::Matrix<double, 6, Eigen::Dynamic> centred = w.colwise() - mean;
  const Mat<6, 6> scatter = centred * centred.transpose();
  const Eigen::SelfAdjointEigenSolver<Mat<6, 6>> eig(scatter, Eigen::EigenvaluesOnly);
  const Vec<6> s = eig.eigenvalues().cwiseMax(0.0).cwiseSqrt();
  const double largest = s.maxCoeff();
  if (!(largest > 0.0)) return 0;
  return static_cast<int>((s.array() > relative_tolerance * largest).count());
}

/// GraspIt's torque scale ("maxRadius"): the largest distance (m) from \p centre to a point of the
/// shapes, all in one frame (e.g. an object's shapes in the object frame and its centre of mass).
/// Exact for every ShapeType: a box's farthest vertex, a sphere's or capsule's farthest end plus
/// its radius, a cylinder's farthest rim point. Throws topograsp::invalid_argument naming
/// "shapes" when there are none, "centre" for a non-finite centre, or "shapes[i].size" for a
/// non-finite or negative size.
[[nodiscard]] inline double max_radius(std::span<const ShapeSpec> shapes, const Vec3& centre) {
  if (shapes.empty()) detail::throw_invalid_argument("shapes", "expected at least one shape");
  require_finite(centre, "centre");
  double out = 0.0;
  for (std::size_t i = 0; i < shapes.size(); ++i) {
    const ShapeSpec& s = shapes[i];
    for (const double v : s.size) require_non_negative(v, "shapes[" + std::to_string(i) + "].size");
    // The centre in the shape's frame.
    const Vec3 c = s.pose.rotation().transpose() * (centre - s.pose.translation());
    const double a = s.size[0], b = s.size[1], h = s.size[2];
    double d = 0.0;
    switch (s.type) {
      case ShapeType::sphere:
        d = c.norm() + a;
        break;
      case ShapeType::capsule:
        d = std::max((c - Vec3(0, 0, b)).norm(), (c - Vec3(0, 0, -b)).norm()) + a;
        break;
      case ShapeType::box:
        d = (c.cwiseAbs() + Vec3(a, b, h)).norm();  // the vertex on the far side of each axis
        break;
      case ShapeType::cylinder:
        d = std::hypot(c.head<2>().norm() + a, std::abs(c.z()) + b);
        break;
    }
    out = std::max(out, d);
  }
  return out;
}

#ifdef TOPOGRASP_EXTERN_HAND_INDEPENDENT
// Compiled once, in the one translation unit that includes grasp/hand_independent.hpp
// (docs/benchmarks.md, "Compiling the transfer once per program").
extern template int affine_dimension<void>(const Eigen::Matrix<double, 6, Eigen::Dynamic>&, double);
#endif

}  // namespace topograsp
