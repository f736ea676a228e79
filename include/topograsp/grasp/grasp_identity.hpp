// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Which grasps are the same grasp: an object's symmetries (the rotations that map it onto
/// itself, found from its principal axes and checked on its shape and materials), and the
/// clusters of grasps that differ only by such a rotation and by less than a stated tolerance in
/// hand pose and joints. Statistics over demonstrations count clusters, not copies
/// (docs/evaluation.md, "Distinct grasps").
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <vector>

#include <Eigen/Eigenvalues>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/geometry/signed_distance.hpp>
#include <topograsp/grasp/object.hpp>

namespace topograsp {

/// The rotations that map an object onto itself, about its centre of mass.
struct ObjectSymmetry {
  Vec3 centre = Vec3::Zero();  ///< the point they turn about (object frame): the centre of mass
  /// Rotations (object frame) that map the object's shape and materials onto themselves; the
  /// identity first.
  std::vector<Mat3> rotations{Mat3::Identity()};
  /// A unit axis through `centre` about which every rotation maps the object onto itself (a
  /// cylinder's, a sphere's one axis); empty if none.
  std::optional<Vec3> axis;
  /// Every rotation about `centre` maps the object onto itself (a sphere).
  bool isotropic = false;
};

namespace detail {

// The material label of point x of the object: 1 + the index of the density of the first part
// holding x, 0 outside; `margin` returns -1 when x is within margin of a part's surface (no
// label: too close to tell).
inline int material_label(const GraspObject& o, const std::vector<Primitive>& parts, const Vec3& x,
                          double margin) {
  int label = 0;
  for (std::size_t i = 0; i < parts.size(); ++i) {
    const double d = signed_distance(parts[i], x);
    if (std::abs(d) <= margin) return -1;
    if (d < 0.0 && label == 0) {
      // Parts of equal density share a label (the first such part's): a symmetry may exchange
      // them.
      const auto density = [&](std::size_t k) {
        return o.densities.empty() ? 1.0 : o.densities[k];
      };
      std::size_t first = 0;
      while (density(first) != density(i)) ++first;
      label = static_cast<int>(first) + 1;
    }
  }
  return label;
}

// True if rotating the object by R about c maps every grid point's label onto the same label
// (points within `margin` of a surface skipped).
inline bool maps_onto_itself(const GraspObject& o, const std::vector<Primitive>& parts,
                             const std::vector<Vec3>& grid, const Vec3& c, const Mat3& R,
                             double margin) {
  for (const Vec3& x : grid) {
    const int a = material_label(o, parts, x, margin);
    if (a < 0) continue;
    const int b = material_label(o, parts, Vec3(c + R * (x - c)), margin);
    if (b >= 0 && a != b) return false;
  }
  return true;
}

// The angle of rotation R (rad, in [0, pi]).
inline double rotation_angle(const Mat3& R) {
  return std::acos(std::clamp(0.5 * (R.trace() - 1.0), -1.0, 1.0));
}

}  // namespace detail

/// The symmetries of \p object: the candidates are the rotations by 90, 180 and 270 degrees
/// about each principal axis of inertia through the centre of mass, and every rotation about a
/// principal axis whose two other moments are equal (within 1e-3 relative; checked at six
/// angles, multiples of 2 pi / 7); a candidate is kept if it maps the parts, and which material
/// fills them, onto themselves at every point of a 24^3 grid over the object's bounding box
/// farther than \p tolerance (m) from any part's surface. An object with two such axes is
/// isotropic (a sphere: every rotation; the discrete ones are then not listed). Throws as
/// GraspObject::validate() for a bad object and topograsp::invalid_argument naming "tolerance"
/// unless it is positive and finite.
[[nodiscard]] inline ObjectSymmetry object_symmetry(const GraspObject& object,
                                                    double tolerance = 0.002) {
  object.validate();
  require_positive(tolerance, "tolerance");
  ObjectSymmetry out;
  out.centre = object.centre_of_mass();
  const Composite shape = object.composite();
  const std::vector<Primitive> parts(shape.parts().begin(), shape.parts().end());
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  for (const Primitive& p : parts) {
    const double r = p.bounding_radius();
    lo = lo.cwiseMin(p.p - Vec3::Constant(r));
    hi = hi.cwiseMax(p.p + Vec3::Constant(r));
  }
  constexpr int n = 24;
  std::vector<Vec3> grid;
  grid.reserve(n * n * n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        grid.push_back(lo + (hi - lo).cwiseProduct(Vec3(i + 0.5, j + 0.5, k + 0.5) / n));
  const Mat3 inertia =
      object.inertial
          ? object.inertial->inertia
          : body_mass_properties<double>(object.parts, 0.0, 0.0, object.densities).inertia;
  const Eigen::SelfAdjointEigenSolver<Mat3> eig(inertia);
  const Vec3 moments = eig.eigenvalues();
  const Mat3 axes = eig.eigenvectors();
  const auto turn = [](const Vec3& axis, double angle) {
    return Mat3(Eigen::AngleAxisd(angle, axis.normalized()));
  };
  for (int a = 0; a < 3 && !out.axis; ++a) {
    const double m1 = moments[(a + 1) % 3], m2 = moments[(a + 2) % 3];
    if (!(std::abs(m1 - m2) <= 1e-3 * std::max(m1, m2))) continue;
    bool every = true;
    for (int k = 1; k < 7 && every; ++k)
      every = detail::maps_onto_itself(object, parts, grid, out.centre,
                                       turn(axes.col(a), 2.0 * pi * k / 7.0), tolerance);
    if (every) out.axis = Vec3(axes.col(a).normalized());
  }
  // A second axis of continuous symmetry (all moments equal) makes every rotation one.
  if (out.axis && std::abs(moments[0] - moments[2]) <= 1e-3 * moments[2]) {
    const Vec3 other = detail::any_perpendicular<double>(*out.axis);
    bool every = true;
    for (int k = 1; k < 7 && every; ++k)
      every = detail::maps_onto_itself(object, parts, grid, out.centre,
                                       turn(other, 2.0 * pi * k / 7.0), tolerance);
    if (every) {
      out.isotropic = true;
      return out;
    }
  }
  for (int a = 0; a < 3; ++a)
    for (const double angle : {0.5 * pi, pi, 1.5 * pi}) {
      const Mat3 R = turn(axes.col(a), angle);
      // Rotations about the continuous axis are already covered by it.
      if (out.axis && std::abs(std::abs(axes.col(a).dot(*out.axis)) - 1.0) < 1e-9) continue;
      if (detail::maps_onto_itself(object, parts, grid, out.centre, R, tolerance))
        out.rotations.push_back(R);
    }
  return out;
}

/// How close two grasps must be to count as the same grasp, after the object's symmetry.
struct GraspTolerance {
  double position = 0.01;    ///< of the hand's root link (m). Default 1 cm.
  double angle = deg(15.0);  ///< of its orientation (rad). Default 15 degrees.
  double joint = deg(10.0);  ///< of every joint (rad or m). Default 10 degrees.
};

/// True if the grasp with root pose \p a (object frame) and joints \p qa is the grasp \p b,
/// \p qb up to a symmetry of the object: some rotation of \p symmetry (for a symmetry axis, the
/// rotation about it that carries a's root position, or if that lies on the axis its x axis,
/// closest to b's) brings a's root within tolerance.position and tolerance.angle of b's, and
/// every joint differs by at most tolerance.joint. Grasps of different joint counts are not the
/// same.
template <class QA, class QB>
[[nodiscard]] bool same_grasp(const Eigen::Isometry3d& a, const QA& qa, const Eigen::Isometry3d& b,
                              const QB& qb, const ObjectSymmetry& symmetry,
                              const GraspTolerance& tolerance = {}) {
  if (qa.size() != qb.size() || (qa - qb).cwiseAbs().maxCoeff() > tolerance.joint) return false;
  const Vec3 c = symmetry.centre;
  if (symmetry.isotropic) {
    // The one rotation that turns a's root onto b's; the positions must then agree.
    const Mat3 T = b.linear() * a.linear().transpose();
    return (c + T * (a.translation() - c) - b.translation()).norm() <= tolerance.position;
  }
  for (const Mat3& S : symmetry.rotations) {
    Mat3 R = S * a.linear();
    Vec3 p = c + S * (a.translation() - c);
    if (symmetry.axis) {
      const Vec3& u = *symmetry.axis;
      const auto flat = [&](const Vec3& v) { return Vec3(v - v.dot(u) * u); };
      Vec3 from = flat(p - c), to = flat(b.translation() - c);
      if (from.norm() < 1e-3 || to.norm() < 1e-3) {
        from = flat(R.col(0));
        to = flat(b.linear().col(0));
      }
      if (from.norm() > 1e-9 && to.norm() > 1e-9) {
        const double theta = std::atan2(u.dot(from.cross(to)), from.dot(to));
        const Mat3 T(Eigen::AngleAxisd(theta, u));
        R = T * R;
        p = c + T * (p - c);
      }
    }
    if ((p - b.translation()).norm() <= tolerance.position &&
        detail::rotation_angle(R.transpose() * b.linear()) <= tolerance.angle)
      return true;
  }
  return false;
}

/// The clusters of grasps \p poses (root poses, object frame) with joints \p joints: grasps that
/// are the same (same_grasp()) share a cluster, and so, by chains of such pairs, do their
/// clusters (single linkage). Returns each grasp's cluster as the index of the cluster's first
/// grasp. Throws topograsp::invalid_argument naming "joints" unless there is one per pose.
template <class Q>
[[nodiscard]] std::vector<int> grasp_clusters(std::span<const Eigen::Isometry3d> poses,
                                              std::span<const Q> joints,
                                              const ObjectSymmetry& symmetry,
                                              const GraspTolerance& tolerance = {}) {
  if (poses.size() != joints.size())
    detail::throw_invalid_argument("joints", "expected one per pose (" +
                                                 std::to_string(poses.size()) + "), got " +
                                                 std::to_string(joints.size()));
  std::vector<int> parent(poses.size());
  std::iota(parent.begin(), parent.end(), 0);
  const auto root = [&](int i) {
    while (parent[static_cast<std::size_t>(i)] != i) i = parent[static_cast<std::size_t>(i)];
    return i;
  };
  for (std::size_t i = 0; i < poses.size(); ++i)
    for (std::size_t j = 0; j < i; ++j)
      if (same_grasp(poses[i], joints[i], poses[j], joints[j], symmetry, tolerance)) {
        const int ri = root(static_cast<int>(i)), rj = root(static_cast<int>(j));
        parent[static_cast<std::size_t>(std::max(ri, rj))] = std::min(ri, rj);
      }
  std::vector<int> out(poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) out[i] = root(static_cast<int>(i));
  return out;
}

}  // namespace topograsp
