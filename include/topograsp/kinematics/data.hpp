// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// KinematicsData: every result of forward kinematics for one model, sized at compile time.
#pragma once

#include <array>
#include <type_traits>

#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/model/model.hpp>

namespace topograsp {

/// Results and scratch space of forward kinematics for the model \p M (a reference to a constexpr
/// Model). Holds no heap memory; filled by forward_kinematics(), read by the Jacobian functions.
template <const auto& M>
  requires KinematicModel<decltype(M)>
struct KinematicsData {
  using ModelType = std::remove_cvref_t<decltype(M)>;
  /// The model, available as a constant expression.
  static constexpr const ModelType& model = M;
  static constexpr int nq = M.nq;
  static constexpr int n_links = static_cast<int>(ModelType::n_links);
  static constexpr int n_frames = static_cast<int>(ModelType::n_frames);
  using Config = Vec<nq>;

  Config q = Config::Zero();                    ///< the configuration of the last call (dim nq)
  std::array<Mat3, ModelType::n_links> R{};     ///< world rotation of each link frame
  std::array<Vec3, ModelType::n_links> p{};     ///< world position of each link frame (m)
  std::array<Vec3, ModelType::n_links> axis{};  ///< world joint axis of each link (zero if fixed)
  std::array<Mat3, ModelType::n_frames> frame_R{};  ///< world rotation of each named frame
  std::array<Vec3, ModelType::n_frames> frame_p{};  ///< world position of each named frame (m)
};

/// The lower joint limits of \p M (dim nq).
template <const auto& M>
[[nodiscard]] Vec<M.nq> lower_limits() noexcept {
  Vec<M.nq> v;
  for (int i = 0; i < M.nq; ++i) v[i] = M.joint_spec(i).lower;
  return v;
}

/// The upper joint limits of \p M (dim nq).
template <const auto& M>
[[nodiscard]] Vec<M.nq> upper_limits() noexcept {
  Vec<M.nq> v;
  for (int i = 0; i < M.nq; ++i) v[i] = M.joint_spec(i).upper;
  return v;
}

/// The closing direction of each joint of \p M (+1, -1 or 0, dim nq).
template <const auto& M>
[[nodiscard]] Vec<M.nq> closing_directions() noexcept {
  Vec<M.nq> v;
  for (int i = 0; i < M.nq; ++i) v[i] = M.joint_spec(i).closing;
  return v;
}

/// \p q clamped into the joint limits of \p M. NaN entries stay NaN (check first).
template <const auto& M, EigenDense D>
[[nodiscard]] Vec<M.nq> clamp_to_limits(const D& q) noexcept {
  Vec<M.nq> out = q;
  for (int i = 0; i < M.nq; ++i) {
    const LinkSpec& s = M.joint_spec(i);
    if (out[i] < s.lower) out[i] = s.lower;
    if (out[i] > s.upper) out[i] = s.upper;
  }
  return out;
}

/// Throws topograsp::invalid_argument naming \p argument unless \p q has M.nq finite entries.
template <const auto& M, EigenDense D>
void require_configuration(const D& q, std::string_view argument = "q") {
  require_size(q, M.nq, argument);
  require_finite(q, argument);
}

}  // namespace topograsp
