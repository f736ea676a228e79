// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Virtual-finger mapping (Arbib, Iberall and Lyons 1985): the target's thumb opposes its other
/// fingers along and across the source's palm or pad opposition.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <utility>

#include <topograsp/grasp/transfer/common.hpp>

namespace topograsp {

namespace detail {

// Hand M's opposition at kinematics d (its root frame): its thumb tip (the first virtual finger)
// and the centroid of its other fingertips (the second).
template <const auto& M>
std::pair<Vec3, Vec3> opposition(const KinematicsData<M>& d) {
  Vec3 fingers = Vec3::Zero();
  for (int f = 0; f < static_cast<int>(M.fingers.size()); ++f)
    if (f != M.thumb) fingers += world_point(d, finger_tip<M>(f));
  fingers /= static_cast<double>(M.fingers.size() - 1);
  return {world_point(d, finger_tip<M>(M.thumb)), fingers};
}

// The source's opposition (object frame): its thumb tip and the centroid of its other fingertips.
inline std::pair<Vec3, Vec3> opposition(const SourceGrasp& s) {
  Vec3 fingers = Vec3::Zero();
  for (std::size_t f = 0; f < s.digits.size(); ++f)
    if (static_cast<int>(f) != s.thumb) fingers += s.root * s.digits[f].tip;
  fingers /= static_cast<double>(s.digits.size() - 1);
  return {s.root * s.digits[static_cast<std::size_t>(s.thumb)].tip, fingers};
}

// The length (m) of the object's chord along the line c + s u (u unit): the inside interval of
// samples each millimetre for |s| <= 0.3 m that contains c or, if c is outside, lies nearest it;
// 0 if the line misses the object.
inline double chord_length(const Composite& shape, const Vec3& c, const Vec3& u) {
  constexpr int n = 300;
  std::array<bool, 2 * n + 1> inside{};
  for (int i = -n; i <= n; ++i)
    inside[static_cast<std::size_t>(i + n)] = nearest_surface(shape, c + 1e-3 * i * u).distance < 0;
  int best = -1;  // a sample in the chosen interval
  for (int k = 0; k <= n && best < 0; ++k)
    for (const int i : {n + k, n - k})
      if (inside[static_cast<std::size_t>(i)]) best = i;
  if (best < 0) return 0.0;
  int lo = best, hi = best;
  while (lo > 0 && inside[static_cast<std::size_t>(lo - 1)]) --lo;
  while (hi < 2 * n && inside[static_cast<std::size_t>(hi + 1)]) ++hi;
  return 1e-3 * (hi - lo + 1);
}

}  // namespace detail

/// The openings (rad) the virtual-finger mapping chooses among: 0 to 1.5 in steps of 0.01.
inline constexpr int k_virtual_finger_openings = 151;

/// Virtual-finger mapping (Arbib, Iberall and Lyons 1985; Iberall 1987), the power-grasp
/// baseline, from any hand to any hand. In the source grasp the fingers other than the thumb act
/// as one virtual finger (the centroid of their tips) that either the palm opposes (palm
/// opposition, a power grasp: a shape of the source's palm link touches the object, within
/// sim.contact_gap and the stability suite's touch_distance) or the thumb (pad opposition: only
/// the digits touch). In Target the thumb tip opposes the centroid of its other fingertips:
/// - pad: Target's opposition along the source's, the midpoints together, Target's approach the
///   source's made orthogonal to it; the aperture the source's (thumb tip to the fingers'
///   centroid);
/// - palm: Target placed as the transplant (its grasp frame at the source's: grasp_frame); the
///   aperture the object's chord along the "up" axis (thumb to fingers) through the source's grasp
///   centre (chord_length).
/// Target is opened as opened_preshape(opening, base_preshape) at the opening (0 to 1.5 rad) whose
/// aperture (thumb tip to the centroid of the other tips) is nearest that aperture plus
/// options.virtual_finger_margin (the pre-shape rule, stated before any run); then opened until
/// clear of the object (open_hand_until_clear), backed off along its approach only if it still
/// overlaps, or moved on until contact (at most final_approach), closed until contact and judged
/// (with \p second if set).
///
/// Not planned (planned false, reason says why) for a source that unusable_source refuses, a pad
/// opposition shorter than 1 mm or along the source's approach (no axis to turn the hand by), or a
/// hand that cannot be placed clear of the object.
template <const auto& Target>
  requires HandModel<decltype(Target)>
[[nodiscard]] HandTransfer<Target> virtual_finger_grasp(const GraspObject& object,
                                                        const SourceGrasp& source,
                                                        const TransferOptions& options = {},
                                                        const SecondJudge<Target>& second = {}) {
  detail::TransferRun<Target> run(TransferMethod::virtual_finger, unusable_source(source), options);
  if (run.refused()) return run.unplanned();
  const auto [thumb_s, fingers_s] = detail::opposition(source);
  const Composite shape = object.composite();  // parts() views it: keep it alive
  // Palm opposition when the palm touches the object (within the approach's contact gap and the
  // stability suite's touch distance), pad opposition when only the digits do.
  const Composite in_hand = object.composite(source.root.inverse());
  double palm_distance = std::numeric_limits<double>::infinity();
  for (const Primitive& palm : source.palm)
    for (const Primitive& part : in_hand.parts())
      palm_distance = std::min(palm_distance, signed_distance(palm, part).distance);
  const bool pad =
      !(palm_distance <= options.sim.contact_gap + options.sim.stability.touch_distance);
  const Eigen::Isometry3d target = source.grasp_frame;
  const Vec3 approach = target.linear().col(2);
  const Vec3 opposition = pad ? Vec3(fingers_s - thumb_s) : Vec3(target.linear().col(0));
  const double aperture =
      pad ? opposition.norm() : detail::chord_length(shape, target.translation(), opposition);
  if (pad && (!(aperture >= 1e-3) || opposition.cross(approach).norm() < 1e-3 * aperture))
    return run.unplanned("the source's opposition is too short or along its approach");
  // The opening whose aperture is nearest the goal.
  const double goal = aperture + options.virtual_finger_margin;
  const Vec<Target.nq> base = base_preshape<Target>(options);
  Vec<Target.nq> preshape = base;
  double best = std::numeric_limits<double>::infinity();
  KinematicsData<Target> d;
  for (int i = 0; i < k_virtual_finger_openings; ++i) {
    const Vec<Target.nq> q = opened_preshape<Target>(0.01 * i, base);
    forward_kinematics(d, q);
    const auto [thumb, fingers] = detail::opposition<Target>(d);
    const double error = std::abs((fingers - thumb).norm() - goal);
    if (error < best) {
      best = error;
      preshape = q;
    }
  }
  Eigen::Isometry3d root = root_for_grasp_frame<Target>(target, preshape);
  if (pad) {  // Target's opposition along the source's, the midpoints together
    forward_kinematics(d, preshape);
    const auto [thumb, fingers] = detail::opposition<Target>(d);
    root.linear() =
        palm_rotation(HandAxes{(fingers - thumb).normalized(), grasp_approach<Target>(preshape)},
                      opposition, approach);
    root.translation() = 0.5 * (thumb_s + fingers_s) - root.linear() * (0.5 * (thumb + fingers));
  }
  run.r.reason = pad ? "pad opposition" : "palm opposition";
  return run.open_place_and_judge(object, root, preshape, options, second);
}

}  // namespace topograsp
