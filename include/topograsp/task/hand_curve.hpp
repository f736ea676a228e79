// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// HandCurve and hand_curves(): the piecewise-linear curves through a hand (paper III.A), from the
/// thumb tip through the thumb's joints, the palm centre and finger i's joints to its tip.
#pragma once

#include <array>
#include <cstddef>
#include <string_view>

#include <topograsp/kinematics/forward.hpp>

namespace topograsp {

/// One hand curve: the link points it passes, thumb tip first, finger tip last.
template <std::size_t Capacity>
struct HandCurve {
  std::array<LinkPoint, Capacity> points{};  ///< the first \c size entries are used
  int size = 0;                              ///< number of points
  int finger = -1;                           ///< index (in the model's fingers) of finger i
  friend constexpr bool operator==(const HandCurve&, const HandCurve&) = default;
};

/// The number of hand curves of the hand model \p M: one per finger that is not the thumb.
template <const auto& M>
  requires HandModel<decltype(M)>
inline constexpr int hand_curve_count =
    static_cast<int>(std::remove_cvref_t<decltype(M)>::n_fingers) - 1;

namespace detail {
template <const auto& M>
consteval int hand_curve_capacity_of() {
  int longest = 0;
  for (std::size_t f = 0; f < M.fingers.size(); ++f)
    if (static_cast<int>(f) != M.thumb && M.fingers[f].size > longest) longest = M.fingers[f].size;
  return M.fingers[static_cast<std::size_t>(M.thumb)].size + 1 + longest;
}
}  // namespace detail

/// The most points any hand curve of \p M has: thumb points + palm + the longest finger.
template <const auto& M>
  requires HandModel<decltype(M)>
inline constexpr int hand_curve_capacity = detail::hand_curve_capacity_of<M>();

/// The hand curves of a hand model (evaluated at compile time), gamma_i for the fingers in model
/// order, the thumb skipped: thumb tip, ..., thumb base, palm centre, finger base, ..., finger tip.
/// The paper writes them for fingers f_1..f_{n-1} with thumb f_n; any hand model works.
template <const auto& M>
  requires HandModel<decltype(M)>
[[nodiscard]] consteval auto hand_curves() {
  constexpr auto cap = static_cast<std::size_t>(hand_curve_capacity<M>);
  std::array<HandCurve<cap>, static_cast<std::size_t>(hand_curve_count<M>)> out{};
  const Finger& thumb = M.fingers[static_cast<std::size_t>(M.thumb)];
  std::size_t c = 0;
  for (std::size_t f = 0; f < M.fingers.size(); ++f) {
    if (static_cast<int>(f) == M.thumb) continue;
    HandCurve<cap>& curve = out[c++];
    curve.finger = static_cast<int>(f);
    for (int k = thumb.size - 1; k >= 0; --k)
      curve.points[static_cast<std::size_t>(curve.size++)] =
          thumb.points[static_cast<std::size_t>(k)];
    curve.points[static_cast<std::size_t>(curve.size++)] = M.palm;
    const Finger& finger = M.fingers[f];
    for (int k = 0; k < finger.size; ++k)
      curve.points[static_cast<std::size_t>(curve.size++)] =
          finger.points[static_cast<std::size_t>(k)];
  }
  return out;
}

/// The hand curves of \p M as a constant (hand_curves<M>() stored once).
template <const auto& M>
  requires HandModel<decltype(M)>
inline constexpr auto hand_curves_of = hand_curves<M>();

/// The link points of hand curve \p C of \p M as an array of exactly its length (for tasks on
/// fixed chains such as WritheTask).
template <const auto& M, int C>
  requires HandModel<decltype(M)>
[[nodiscard]] consteval auto hand_curve_chain() {
  constexpr auto& curve = hand_curves_of<M>[static_cast<std::size_t>(C)];
  std::array<LinkPoint, static_cast<std::size_t>(curve.size)> out{};
  for (std::size_t k = 0; k < out.size(); ++k) out[k] = curve.points[k];
  return out;
}

/// The index of the hand curve of \p M that ends at the finger named \p finger; -1 if there is no
/// such finger or it is the thumb.
template <const auto& M>
  requires HandModel<decltype(M)>
[[nodiscard]] constexpr int hand_curve_index(std::string_view finger) noexcept {
  const auto& curves = hand_curves_of<M>;
  for (std::size_t i = 0; i < curves.size(); ++i)
    if (M.fingers[static_cast<std::size_t>(curves[i].finger)].spec.name.view() == finger)
      return static_cast<int>(i);
  return -1;
}

/// The world positions of the points of hand curve \p curve of \p M into \p out (at least
/// hand_curve_capacity<M> entries); returns the number of points written. Requires
/// forward_kinematics(d, q) first. No checks: \p curve must be in [0, hand_curve_count<M>).
template <const auto& M>
  requires HandModel<decltype(M)>
int hand_curve_points(
    const KinematicsData<M>& d, int curve,
    std::array<Vec3, static_cast<std::size_t>(hand_curve_capacity<M>)>& out) noexcept {
  const auto& c = hand_curves_of<M>[static_cast<std::size_t>(curve)];
  for (int k = 0; k < c.size; ++k)
    out[static_cast<std::size_t>(k)] = world_point(d, c.points[static_cast<std::size_t>(k)]);
  return c.size;
}

}  // namespace topograsp
