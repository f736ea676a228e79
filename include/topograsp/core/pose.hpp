// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Pose: a rigid transform as a literal type, for constexpr models; and its Eigen views.
#pragma once

#include <array>

#include <topograsp/core/cmath.hpp>
#include <topograsp/core/eigen.hpp>

namespace topograsp {

/// A rigid transform x_parent = R * x_child + p, stored as plain arrays so that it can live in a
/// constexpr model (Eigen 3.4 types are not literal types). R is row-major.
struct Pose {
  std::array<double, 9> R{1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0};
  std::array<double, 3> p{0.0, 0.0, 0.0};

  /// This pose with the translation replaced by (x, y, z).
  [[nodiscard]] constexpr Pose at(double x, double y, double z) const noexcept {
    Pose out = *this;
    out.p = {x, y, z};
    return out;
  }
  /// This pose followed by a rotation given as roll, pitch, yaw (URDF: Rz(y) Ry(p) Rx(r)).
  [[nodiscard]] constexpr Pose rpy(double roll, double pitch, double yaw) const noexcept;
  /// This pose followed by a rotation given as a unit quaternion (w, x, y, z); normalised here.
  [[nodiscard]] constexpr Pose quat(double w, double x, double y, double z) const noexcept;

  /// The rotation as an Eigen matrix.
  [[nodiscard]] Mat3 rotation() const noexcept {
    return Eigen::Map<const Eigen::Matrix<double, 3, 3, Eigen::RowMajor>>(R.data());
  }
  /// The translation as an Eigen vector.
  [[nodiscard]] Vec3 translation() const noexcept { return Eigen::Map<const Vec3>(p.data()); }
  [[nodiscard]] Eigen::Isometry3d isometry() const noexcept {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = rotation();
    T.translation() = translation();
    return T;
  }
  friend constexpr bool operator==(const Pose&, const Pose&) = default;
};

/// The composition a * b (b expressed in a's frame).
[[nodiscard]] constexpr Pose operator*(const Pose& a, const Pose& b) noexcept {
  Pose c;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double s = 0.0;
      for (int k = 0; k < 3; ++k)
        s += a.R[static_cast<std::size_t>(3 * i + k)] * b.R[static_cast<std::size_t>(3 * k + j)];
      c.R[static_cast<std::size_t>(3 * i + j)] = s;
    }
    double t = a.p[static_cast<std::size_t>(i)];
    for (int k = 0; k < 3; ++k)
      t += a.R[static_cast<std::size_t>(3 * i + k)] * b.p[static_cast<std::size_t>(k)];
    c.p[static_cast<std::size_t>(i)] = t;
  }
  return c;
}

/// The inverse transform.
[[nodiscard]] constexpr Pose inverse(const Pose& a) noexcept {
  Pose b;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 3; ++j) b.R[3 * i + j] = a.R[3 * j + i];
  for (std::size_t i = 0; i < 3; ++i)
    b.p[i] = -(b.R[3 * i] * a.p[0] + b.R[3 * i + 1] * a.p[1] + b.R[3 * i + 2] * a.p[2]);
  return b;
}

/// A pure translation.
[[nodiscard]] constexpr Pose translation(double x, double y, double z) noexcept {
  return Pose{}.at(x, y, z);
}

/// A pure rotation from roll, pitch, yaw (fixed axes X, then Y, then Z: R = Rz(y) Ry(p) Rx(r)).
[[nodiscard]] constexpr Pose rotation_rpy(double roll, double pitch, double yaw) noexcept {
  const double cr = cmath::cos(roll), sr = cmath::sin(roll);
  const double cp = cmath::cos(pitch), sp = cmath::sin(pitch);
  const double cy = cmath::cos(yaw), sy = cmath::sin(yaw);
  Pose out;
  out.R = {cy * cp,
           cy * sp * sr - sy * cr,
           cy * sp * cr + sy * sr,
           sy * cp,
           sy * sp * sr + cy * cr,
           sy * sp * cr - cy * sr,
           -sp,
           cp * sr,
           cp * cr};
  return out;
}

/// A pure rotation from a quaternion (w, x, y, z), normalised here.
[[nodiscard]] constexpr Pose rotation_quat(double w, double x, double y, double z) noexcept {
  const double n = cmath::sqrt(w * w + x * x + y * y + z * z);
  if (n > 0.0) {
    w /= n;
    x /= n;
    y /= n;
    z /= n;
  }
  Pose out;
  out.R = {1 - 2 * (y * y + z * z), 2 * (x * y - w * z),     2 * (x * z + w * y),
           2 * (x * y + w * z),     1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
           2 * (x * z - w * y),     2 * (y * z + w * x),     1 - 2 * (x * x + y * y)};
  return out;
}

/// A pure rotation by \p angle about the unit axis (x, y, z) (Rodrigues).
[[nodiscard]] constexpr Pose rotation_axis_angle(double x, double y, double z,
                                                 double angle) noexcept {
  const double c = cmath::cos(angle), s = cmath::sin(angle), t = 1.0 - c;
  Pose out;
  out.R = {t * x * x + c,     t * x * y - s * z, t * x * z + s * y,
           t * x * y + s * z, t * y * y + c,     t * y * z - s * x,
           t * x * z - s * y, t * y * z + s * x, t * z * z + c};
  return out;
}

constexpr Pose Pose::rpy(double roll, double pitch, double yaw) const noexcept {
  return *this * rotation_rpy(roll, pitch, yaw);
}

constexpr Pose Pose::quat(double w, double x, double y, double z) const noexcept {
  return *this * rotation_quat(w, x, y, z);
}

/// Shorthand: the pose at translation (x, y, z) with no rotation; chain .rpy() or .quat().
[[nodiscard]] constexpr Pose at(double x, double y, double z) noexcept {
  return translation(x, y, z);
}

/// A Pose from an Eigen isometry (run time).
[[nodiscard]] inline Pose to_pose(const Eigen::Isometry3d& T) noexcept {
  Pose out;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) out.R[static_cast<std::size_t>(3 * i + j)] = T.linear()(i, j);
    out.p[static_cast<std::size_t>(i)] = T.translation()(i);
  }
  return out;
}

/// Whether \p R is a rotation: orthonormal to \p tolerance (R' R is approximately the identity,
/// Eigen's isApprox) with a determinant that is not negative. False for any NaN.
[[nodiscard]] inline bool is_rotation(const Mat3& R, double tolerance = 1e-6) noexcept {
  return (R.transpose() * R).isApprox(Mat3::Identity(), tolerance) && !(R.determinant() < 0.0);
}

namespace detail {

/// The rotation of a Pose converted to the scalar type S.
template <class S>
[[nodiscard]] Mat<3, 3, S> rotation_of(const Pose& p) noexcept {
  return p.rotation().template cast<S>();
}

/// The translation of a Pose converted to the scalar type S.
template <class S>
[[nodiscard]] Vec<3, S> translation_of(const Pose& p) noexcept {
  return p.translation().template cast<S>();
}

}  // namespace detail

}  // namespace topograsp
