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

#if defined(__GNUC__)
#define TOPOGRASP_ALWAYS_INLINE [[gnu::always_inline]] inline
#else
#define TOPOGRASP_ALWAYS_INLINE inline
#endif

// out = R * v for a vector v known at compile time: zero entries cost nothing, ones no multiply.
template <std::array<double, 3> V>
TOPOGRASP_ALWAYS_INLINE void mul_const_vec(const Mat3& R, Vec3& out) noexcept {
  out.setZero();
  [&]<std::size_t... K>(std::index_sequence<K...>) {
    ((V[K] == 0.0 ? void() : (V[K] == 1.0 ? void(out += R.col(K)) : void(out += V[K] * R.col(K)))),
     ...);
  }(std::make_index_sequence<3>{});
}

// out = R * C for a row-major 3x3 matrix C known at compile time, skipping its zeros.
template <std::array<double, 9> C>
TOPOGRASP_ALWAYS_INLINE void mul_const_mat(const Mat3& R, Mat3& out) noexcept {
  [&]<std::size_t... J>(std::index_sequence<J...>) {
    Vec3 column;
    ((mul_const_vec<std::array<double, 3>{C[J], C[3 + J], C[6 + J]}>(R, column),
      out.col(static_cast<Eigen::Index>(J)) = column),
     ...);
  }(std::make_index_sequence<3>{});
}

// The cross-product matrix K of a unit axis a and K^2, row-major: Rot(a, t) = I + sin t K +
// (1 - cos t) K^2 (Rodrigues).
constexpr std::array<double, 9> cross_matrix(const std::array<double, 3>& a) noexcept {
  return {0.0, -a[2], a[1], a[2], 0.0, -a[0], -a[1], a[0], 0.0};
}
constexpr std::array<double, 9> cross_matrix_squared(const std::array<double, 3>& a) noexcept {
  return {a[0] * a[0] - 1.0, a[0] * a[1],       a[0] * a[2],  //
          a[0] * a[1],       a[1] * a[1] - 1.0, a[1] * a[2],  //
          a[0] * a[2],       a[1] * a[2],       a[2] * a[2] - 1.0};
}

// One link of forward kinematics; everything the model says about the link is a constant here.
template <const auto& M, std::size_t I, class D>
TOPOGRASP_ALWAYS_INLINE void fk_link(KinematicsData<M>& d, const D& q) noexcept {
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
      mul_const_mat<origin.R>(d.R[P], Rj);
    if constexpr (is_zero_translation(origin)) {
      pj = d.p[P];
    } else {
      mul_const_vec<origin.p>(d.R[P], pj);
      pj += d.p[P];
    }
  }
  if constexpr (link.spec.type == JointType::fixed) {
    d.R[I] = Rj;
    d.p[I] = pj;
    d.axis[I].setZero();
  } else {
    constexpr double mult = link.actuated ? 1.0 : link.spec.multiplier;
    constexpr double off = link.actuated ? 0.0 : link.spec.offset;
    const double value = mult * q[link.q] + off;
    constexpr auto k = static_cast<int>(link.axis_kind);
    if constexpr (link.axis_kind != AxisKind::general)
      d.axis[I] = link.axis[static_cast<std::size_t>(k)] * Rj.col(k);
    else
      mul_const_vec<link.axis>(Rj, d.axis[I]);
    if constexpr (link.spec.type == JointType::prismatic) {
      d.R[I] = Rj;
      d.p[I] = pj + value * d.axis[I];
    } else {
      d.p[I] = pj;
      if constexpr (link.axis_kind != AxisKind::general) {
        // Rotation about a coordinate axis: mix the two other columns.
        constexpr int a = (k + 1) % 3, b = (k + 2) % 3;
        const auto [s, c] = sincos(link.axis[static_cast<std::size_t>(k)] * value);
        d.R[I].col(k) = Rj.col(k);
        d.R[I].col(a) = c * Rj.col(a) + s * Rj.col(b);
        d.R[I].col(b) = c * Rj.col(b) - s * Rj.col(a);
      } else {
        // Rj * Rot(a, value) = Rj + sin * (Rj K) + (1 - cos) * (Rj K^2).
        const auto [s, c] = sincos(value);
        Mat3 RK, RK2;
        mul_const_mat<cross_matrix(link.axis)>(Rj, RK);
        mul_const_mat<cross_matrix_squared(link.axis)>(Rj, RK2);
        d.R[I] = Rj + s * RK + (1.0 - c) * RK2;
      }
    }
  }
}

template <const auto& M, std::size_t I>
TOPOGRASP_ALWAYS_INLINE void fk_frame(KinematicsData<M>& d) noexcept {
  constexpr Frame f = M.frames[I];
  constexpr auto L = static_cast<std::size_t>(f.link);
  constexpr Pose offset = f.spec.offset;
  if constexpr (is_identity_rotation(offset))
    d.frame_R[I] = d.R[L];
  else
    mul_const_mat<offset.R>(d.R[L], d.frame_R[I]);
  if constexpr (is_zero_translation(offset)) {
    d.frame_p[I] = d.p[L];
  } else {
    mul_const_vec<offset.p>(d.R[L], d.frame_p[I]);
    d.frame_p[I] += d.p[L];
  }
}

#undef TOPOGRASP_ALWAYS_INLINE

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

/// The world pose of frame \p f as an isometry.
template <const auto& M>
[[nodiscard]] Eigen::Isometry3d frame_pose(const KinematicsData<M>& d, int f) noexcept {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = d.frame_R[static_cast<std::size_t>(f)];
  T.translation() = d.frame_p[static_cast<std::size_t>(f)];
  return T;
}

}  // namespace topograsp
