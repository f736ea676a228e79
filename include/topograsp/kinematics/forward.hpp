// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Forward kinematics of every link and named frame.
#pragma once

#include <utility>

#include <topograsp/core/sincos.hpp>
#include <topograsp/kinematics/data.hpp>

namespace topograsp {

namespace detail {

constexpr bool is_identity_rotation(const Pose& p) noexcept { return p.R == Pose{}.R; }
constexpr bool is_zero_translation(const Pose& p) noexcept {
  return p.p[0] == 0.0 && p.p[1] == 0.0 && p.p[2] == 0.0;
}

// Rotation matrix of angle about the unit axis a (Rodrigues).
inline Mat3 axis_rotation(const std::array<double, 3>& a, double angle) noexcept {
  const auto [s, c] = sincos(angle);
  const double t = 1.0 - c;
  Mat3 r;
  r << t * a[0] * a[0] + c, t * a[0] * a[1] - s * a[2], t * a[0] * a[2] + s * a[1],
      t * a[0] * a[1] + s * a[2], t * a[1] * a[1] + c, t * a[1] * a[2] - s * a[0],
      t * a[0] * a[2] - s * a[1], t * a[1] * a[2] + s * a[0], t * a[2] * a[2] + c;
  return r;
}

// One link of forward kinematics; everything the model says about the link is a constant here.
template <const auto& M, std::size_t I, class D>
inline void fk_link(KinematicsData<M>& d, const D& q) noexcept {
  constexpr Link link = M.links[I];
  constexpr Pose origin = link.spec.origin;
  // Joint frame: parent * origin.
  Mat3 Rj;
  Vec3 pj;
  if constexpr (link.parent < 0) {
    Rj = Pose(origin).rotation();
    pj = Pose(origin).translation();
  } else {
    constexpr auto P = static_cast<std::size_t>(link.parent);
    if constexpr (is_identity_rotation(origin))
      Rj = d.R[P];
    else
      Rj.noalias() = d.R[P] * Pose(origin).rotation();
    if constexpr (is_zero_translation(origin))
      pj = d.p[P];
    else
      pj.noalias() = d.p[P] + d.R[P] * Pose(origin).translation();
  }
  if constexpr (link.spec.type == JointType::fixed) {
    d.R[I] = Rj;
    d.p[I] = pj;
    d.axis[I].setZero();
  } else {
    // The link's own joint is the first of its support: its entry, mimic multiplier and offset.
    constexpr SupportJoint joint = M.support(static_cast<int>(I)).joints[0];
    const double value = joint.multiplier * q[joint.q] + joint.offset;
    constexpr auto k = static_cast<int>(link.axis_kind);
    if constexpr (link.axis_kind != AxisKind::general)
      d.axis[I] = link.axis[static_cast<std::size_t>(k)] * Rj.col(k);
    else
      d.axis[I].noalias() = Rj * Eigen::Map<const Vec3>(link.axis.data());
    if constexpr (link.spec.type == JointType::prismatic) {
      d.R[I] = Rj;
      d.p[I] = pj + value * d.axis[I];
    } else {
      d.p[I] = pj;
      if constexpr (link.axis_kind != AxisKind::general) {
        // Rotation about a coordinate axis: mix the two other columns.
        constexpr int a = (k + 1) % 3, b = (k + 2) % 3;
        const double angle = link.axis[static_cast<std::size_t>(k)] * value;
        const auto [s, c] = sincos(angle);
        d.R[I].col(k) = Rj.col(k);
        d.R[I].col(a) = c * Rj.col(a) + s * Rj.col(b);
        d.R[I].col(b) = c * Rj.col(b) - s * Rj.col(a);
      } else {
        d.R[I].noalias() = Rj * axis_rotation(link.axis, value);
      }
    }
  }
}

template <const auto& M, std::size_t I>
inline void fk_frame(KinematicsData<M>& d) noexcept {
  constexpr Frame f = M.frames[I];
  constexpr auto L = static_cast<std::size_t>(f.link);
  constexpr Pose offset = f.spec.offset;
  if constexpr (is_identity_rotation(offset))
    d.frame_R[I] = d.R[L];
  else
    d.frame_R[I].noalias() = d.R[L] * Pose(offset).rotation();
  if constexpr (is_zero_translation(offset))
    d.frame_p[I] = d.p[L];
  else
    d.frame_p[I].noalias() = d.p[L] + d.R[L] * Pose(offset).translation();
}

}  // namespace detail

/// Computes the world pose of every link and named frame of the model at configuration \p q
/// (dim nq, rad or m), and the world axis of every joint, into \p d. The loop over links is
/// unrolled at compile time; nothing is allocated. No checks: call require_configuration() on
/// untrusted input first (a NaN in q gives NaN poses).
template <const auto& M, EigenDense D>
void forward_kinematics(KinematicsData<M>& d, const D& q) noexcept {
  static_assert(D::RowsAtCompileTime == M.nq || D::RowsAtCompileTime == Eigen::Dynamic,
                "q must have M.nq entries");
  d.q = q;
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (detail::fk_link<M, I>(d, d.q), ...);
  }(std::make_index_sequence<M.n_links>{});
  [&]<std::size_t... I>(std::index_sequence<I...>) {
    (detail::fk_frame<M, I>(d), ...);
  }(std::make_index_sequence<M.n_frames>{});
}

/// The world position of point \p p of link \p link (offset in the link frame).
template <const auto& M>
[[nodiscard]] Vec3 world_point(const KinematicsData<M>& d, const LinkPoint& p) noexcept {
  const auto l = static_cast<std::size_t>(p.link);
  return d.p[l] + d.R[l] * Eigen::Map<const Vec3>(p.offset.data());
}

/// The world pose of link \p l as an isometry: rotation d.R[l], translation d.p[l].
template <const auto& M>
[[nodiscard]] Eigen::Isometry3d link_pose(const KinematicsData<M>& d, int l) noexcept {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = d.R[static_cast<std::size_t>(l)];
  T.translation() = d.p[static_cast<std::size_t>(l)];
  return T;
}

/// The world pose of frame \p f as an isometry.
template <const auto& M>
[[nodiscard]] Eigen::Isometry3d frame_pose(const KinematicsData<M>& d, int f) noexcept {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = d.frame_R[static_cast<std::size_t>(f)];
  T.translation() = d.frame_p[static_cast<std::size_t>(f)];
  return T;
}

}  // namespace topograsp
