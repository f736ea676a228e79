// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// A grasp of any hand as data (SourceGrasp): everything the transfer methods read of the hand
/// they transfer from, taken once from a hand model's grasp (describe_source), so that a transfer
/// compiles once per target hand whatever hand demonstrated the grasp. docs/transfer.md, "Any hand
/// to any hand".
#pragma once

#include <array>
#include <cmath>
#include <string>
#include <vector>

#include <topograsp/geometry/model_shapes.hpp>
#include <topograsp/grasp/hand_grasp.hpp>
#include <topograsp/task/hand_curve.hpp>
#include <topograsp/task/winding.hpp>

namespace topograsp {

/// One digit of a source hand at its grasp.
struct SourceDigit {
  Vec3 tip = Vec3::Zero();  ///< its fingertip (finger_tip), in the source's root frame (m)
  double length = 0.0;      ///< the digit held straight (m): digit_length
};

/// A grasp of a source hand as data: what every transfer method reads of the hand it transfers
/// from. describe_source() takes it from a grasp of any hand model; the methods (transfer_hand()
/// and the baselines) read nothing else, so each is compiled once per target hand.
struct SourceGrasp {
  SourceGrasp() = default;
  /// The grasp \p g of hand \p S (describe_source): a grasp of any hand model converts, so that
  /// every method takes a HandGrasp as it takes a SourceGrasp.
  template <const auto& S>
    requires HandModel<decltype(S)>
  SourceGrasp(const HandGrasp<S>& g);  // NOLINT(google-explicit-constructor)

  std::string hand;                                               ///< the source hand's model name
  Eigen::Isometry3d root = Eigen::Isometry3d::Identity();         ///< its root link, object frame
  Eigen::Isometry3d grasp_frame = Eigen::Isometry3d::Identity();  ///< grasp_frame(), object frame
  Eigen::Isometry3d palm_frame = Eigen::Isometry3d::Identity();   ///< palm_frame(), object frame
  /// The points of each of its curves (hand_curves: the windings' curves), root frame.
  std::vector<std::vector<Vec3>> curves;
  std::vector<SourceDigit> digits;  ///< its fingers, in its hand description's order
  int thumb = 0;                    ///< the thumb's index in digits
  std::vector<Primitive> palm;      ///< the shapes of its palm link, root frame
  /// Why the grasp cannot be transferred (set by describe_source for a grasp that is not finite),
  /// or empty: see unusable_source().
  std::string unusable;
};

namespace detail {

// The first link on the path from M's root to finger f's tip that is on no other finger's path:
// where the digit starts (the human's index_abd and thumb_cmc1, the SDH's knuckle and thumb_1).
template <const auto& M>
int digit_base(int f) {
  const auto on_path = [](int link, int g) {
    for (int l = finger_tip<M>(g).link; l >= 0; l = M.links[static_cast<std::size_t>(l)].parent)
      if (l == link) return true;
    return false;
  };
  int base = finger_tip<M>(f).link;
  for (int l = base; l >= 0; l = M.links[static_cast<std::size_t>(l)].parent) {
    for (int g = 0; g < static_cast<int>(M.fingers.size()); ++g)
      if (g != f && on_path(l, g)) return base;
    base = l;
  }
  return base;
}

// The length (m) of finger f of M held straight (q = 0): the distances between the link origins
// from its digit_base out to its tip.
template <const auto& M>
double digit_length(int f) {
  KinematicsData<M> d;
  forward_kinematics(d, Vec<M.nq>::Zero());
  const int first = digit_base<M>(f);
  Vec3 p = world_point(d, finger_tip<M>(f));
  int l = finger_tip<M>(f).link;
  double length = 0.0;
  for (;;) {
    length += (p - d.p[static_cast<std::size_t>(l)]).norm();
    if (l == first || l <= 0) break;
    p = d.p[static_cast<std::size_t>(l)];
    l = M.links[static_cast<std::size_t>(l)].parent;
  }
  return length;
}

// Why the source grasp g of hand S cannot be transferred (a non-finite pose or joints), or empty.
template <const auto& S>
std::string unusable_source_grasp(const HandGrasp<S>& g) {
  if (!g.root.matrix().allFinite()) return "the source hand pose is not finite";
  if (!g.q.allFinite()) return "the source configuration is not finite";
  return {};
}

}  // namespace detail

/// The grasp \p g of hand \p S as a SourceGrasp: its root pose, grasp and palm frames (grasp_frame,
/// palm_frame), its curves' points, its fingertips and digit lengths, its thumb and its palm link's
/// shapes. A grasp whose pose or joints are not finite gives a SourceGrasp with the hand's name,
/// its pose and the reason alone (unusable), which every method refuses with that reason.
template <const auto& S>
  requires HandModel<decltype(S)>
[[nodiscard]] SourceGrasp describe_source(const HandGrasp<S>& g) {
  SourceGrasp s;
  s.hand = std::string(S.name.view());
  s.root = g.root;
  s.unusable = detail::unusable_source_grasp(g);
  if (!s.unusable.empty()) return s;
  s.grasp_frame = grasp_frame(g);
  s.palm_frame = palm_frame(g);
  KinematicsData<S> d;
  forward_kinematics(d, g.q);
  std::array<Vec3, static_cast<std::size_t>(hand_curve_capacity<S>)> x;
  s.curves.reserve(static_cast<std::size_t>(hand_curve_count<S>));
  for (int c = 0; c < hand_curve_count<S>; ++c) {
    const int n = hand_curve_points(d, c, x);
    s.curves.emplace_back(x.begin(), x.begin() + n);
  }
  s.thumb = S.thumb;
  for (int f = 0; f < static_cast<int>(S.fingers.size()); ++f)
    s.digits.push_back({world_point(d, finger_tip<S>(f)), detail::digit_length<S>(f)});
  for (std::size_t k = 0; k < S.n_shapes; ++k)
    if (S.shapes[k].link == S.palm.link) s.palm.push_back(world_shape(d, k));
  return s;
}

template <const auto& S>
  requires HandModel<decltype(S)>
SourceGrasp::SourceGrasp(const HandGrasp<S>& g) : SourceGrasp(describe_source(g)) {}

/// The human demonstration \p g as a SourceGrasp (its palm pose and joints when closing ended).
[[nodiscard]] inline SourceGrasp describe_source(const HumanGrasp& g) {
  return describe_source(source_grasp(g));
}

/// Why the source grasp \p s cannot be transferred by any method, or empty if it can: the reason
/// describe_source gave (a pose or joints that are not finite); fewer than two digits or a thumb
/// that is not one of them; no curve, or a curve of fewer than two points; a frame that is not
/// finite or not a rigid transform (its rotation orthonormal and proper to 1e-6); or a curve point,
/// fingertip, digit length (finite, at least 0) or palm shape (finite, sizes at least 0) that is
/// not (a SourceGrasp made by hand or read from a file).
[[nodiscard]] inline std::string unusable_source(const SourceGrasp& s) {
  if (!s.unusable.empty()) return s.unusable;
  if (s.digits.size() < 2) return "the source hand has fewer than two fingers";
  if (s.thumb < 0 || s.thumb >= static_cast<int>(s.digits.size()))
    return "the source hand's thumb is not one of its fingers";
  if (s.curves.empty()) return "the source hand has no curve to take windings of";
  for (const Eigen::Isometry3d* T : {&s.root, &s.grasp_frame, &s.palm_frame}) {
    if (!T->matrix().allFinite()) return "the source hand pose is not finite";
    const Eigen::Matrix3d R = T->linear();
    if ((R.transpose() * R - Eigen::Matrix3d::Identity()).norm() > 1e-6 ||
        std::abs(R.determinant() - 1.0) > 1e-6)
      return "a frame of the source hand is not a rigid transform";
  }
  for (const auto& curve : s.curves) {
    if (curve.size() < 2) return "a curve of the source hand has fewer than two points";
    for (const Vec3& p : curve)
      if (!p.allFinite()) return "a curve of the source hand is not finite";
  }
  for (const SourceDigit& digit : s.digits)
    if (!digit.tip.allFinite() || !std::isfinite(digit.length) || !(digit.length >= 0.0))
      return "a fingertip or digit length of the source hand is not finite, or a length below 0";
  for (const Primitive& shape : s.palm)
    if (!shape.R.allFinite() || !shape.p.allFinite() || !shape.size.allFinite() ||
        (shape.size.array() < 0.0).any())
      return "a palm shape of the source hand is not finite, or has a size below 0";
  return {};
}

/// The windings of the source's curves around \p p (object frame), in its curves' order: what
/// hand_windings gives for the source hand's model at its grasp. Requires a source that
/// unusable_source accepts and a finite \p p (the methods check both first).
[[nodiscard]] inline Eigen::VectorXd source_windings(const SourceGrasp& s, const Vec3& p) {
  const Vec3 local = s.root.inverse() * p;
  Eigen::VectorXd w(static_cast<Eigen::Index>(s.curves.size()));
  for (std::size_t c = 0; c < s.curves.size(); ++c)
    w[static_cast<Eigen::Index>(c)] =
        detail::winding_unchecked(s.curves[c].data(), s.curves[c].size(), local);
  return w;
}

}  // namespace topograsp
