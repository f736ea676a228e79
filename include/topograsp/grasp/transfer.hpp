// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The transfer methods: a stable human grasp to the Schunk SDH, by topological synergies (the
/// paper: AICO on the 14-DOF arm + SDH with the human's two largest windings as targets), by the
/// paper's baseline "transplant" (the SDH at the human palm's pose, fingers closed), by
/// fingertip mapping (Rohling and Hollerbach 1993: the SDH's fingertips fitted by least squares to
/// the human's thumb, index and ring tips, scaled and put on the object's surface) and by a
/// virtual-finger mapping (Arbib, Iberall and Lyons 1985: the SDH's thumb opposes its two fingers
/// along the axis and across the width of the human thumb's opposition to the other four digits).
/// Each result is closed until contact and judged by the stability suite, the hand without the
/// arm.
///
/// The SDH's methods are templates with nothing to give (`template <class = void>`): a
/// translation unit that includes this header for another hand does not instantiate the SDH's
/// planner and stepper (docs/architecture.md, "Compile time").
#pragma once

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include <topograsp/aico/solver.hpp>
#include <topograsp/geometry/signed_distance.hpp>
#include <topograsp/grasp/hand_grasp.hpp>
#include <topograsp/grasp/human_grasps.hpp>
#include <topograsp/grasp/transfer_method.hpp>
#include <topograsp/task/axis_task.hpp>
#include <topograsp/task/collision_task.hpp>
#include <topograsp/task/joint_limit_task.hpp>
#include <topograsp/task/line_task.hpp>
#include <topograsp/task/task_set.hpp>

namespace topograsp {

/// The parameters of the transfer methods; every field has a default used by grasp_transfer.
struct TransferOptions {
  GraspSimOptions sim{};  ///< closing and stability suite of the transferred grasp
  /// The SDH's joints before closing: knuckle 0 (fingers facing the thumb), phalanges open.
  Vec<7> sdh_preshape = (Vec<7>() << 0.0, -0.3, 0.3, -0.3, 0.3, -0.3, 0.3).finished();
  /// The arm's start configuration (rad): elbow bent, the hand pointing forward.
  Vec<7> arm_ready = (Vec<7>() << 0.0, 0.5, 0.0, 1.0, 0.0, 0.5, 0.0).finished();
  /// The object is placed so that the human grasp centre lies this far beyond the SDH's grasp
  /// centre at the start, along the approach (m): the plan has to move in.
  double backoff = 0.03;
  AicoOptions aico = [] {
    AicoOptions o;
    o.steps = 40;
    o.duration = 2.0;
    o.max_sweeps = 40;
    o.tolerance = 1e-3;
    return o;
  }();
  /// Where the windings are taken (topological). The centre of mass is the paper's choice;
  /// the nearest point keeps grasps far from it (a hammer's head) informative, docs/results.md.
  WindingReference winding_reference = WindingReference::centre_of_mass;
  double winding_precision_mid = 1e1;  ///< precision of the winding targets on the way
  double winding_precision_end = 1e4;  ///< and at the end
  double collision_margin = 0.015;     ///< m
  double collision_precision = 1e3;
  double approach_precision_mid = 1e1;  ///< the SDH's approach axis along the human's
  double approach_precision_end = 1e3;
  /// The SDH's grasp centre on the human's approach line (the line through the human grasp
  /// centre along the approach), per m^2: where on the object to grasp; where along the line is
  /// left to the windings, the collision task and the final approach. 0 switches it off.
  double line_precision_mid = 1e2;
  double line_precision_end = 1e4;
  double limit_precision = 1e3;  ///< joint limits, as a penalty
  /// After the plan, the hand moves on along its approach until it touches the object, at most
  /// this far (m), before the fingers close, as the demonstrations approach until contact.
  double final_approach = 0.25;
  /// Closing corrections of the topological method (0 = none): after the plan the placed hand is
  /// closed, the windings it closes to correct the targets (target += human's - closed) and the
  /// plan is made again, this many times; the plan whose closed windings are nearest the human's
  /// is kept. Each costs a plan and a closing.
  int closing_corrections = 0;
  /// Least-squares iterations of the fingertip mapping.
  int fingertip_iterations = 100;
  /// Weight of the fingertip fit's pull toward the transplant pose and the pre-shape, per m^2 or
  /// rad^2, against the tip errors in m^2 (1e-4: 1 rad weighs as 1 cm, so the tips are reached).
  double fingertip_prior = 1e-4;
  /// Scale of the source's mapped tip positions about their centroid before they are put on the
  /// object's surface (the target's size over the source's); 0 = the ratio of the mapped digits'
  /// lengths, fingertip_scale<Target, Source>() (human -> SDH: 2.175).
  double fingertip_scale = 0.0;
  /// The virtual-finger mapping opens the target hand until its thumb tip and the centroid of its
  /// other tips lie this much farther apart than the source's aperture (m): room for the SDH's
  /// phalanx (1.4 cm radius) and a clearance, 2 cm on each side.
  double virtual_finger_margin = 0.04;
  /// How far the transplant baseline opens the SDH before it is placed (rad): its proximal
  /// joints at -opening, its distal joints at +opening (the tips kept pointing inward), the
  /// knuckle as in sdh_preshape (transplant_preshape). Default 0.7, the best of a sweep over
  /// 0.3 to 1.1 on the hammer and the bottle, seeds 1 to 4 (docs/results.md): a baseline is
  /// given its best setting, not one known to fail (sdh_preshape's 0.3 fails every bottle grasp).
  double transplant_opening = 0.7;
};

/// One numeric parameter of TransferOptions that a command line or a result file names: its name,
/// its field, its valid range [min, max] (inclusive) and a one-line meaning with its unit.
struct TransferParameter {
  std::string_view name;
  double TransferOptions::* field;
  double min;
  double max;
  std::string_view meaning;
};

/// The numeric parameters of TransferOptions (grasp_transfer --set NAME=VALUE; the "transfer"
/// object of results.json), each with the range set_transfer_parameter accepts. Lengths are in
/// m, precisions are task weights (per m^2 for the line task); 0 switches a task's term off.
inline constexpr std::array<TransferParameter, 15> transfer_parameters{{
    {"backoff", &TransferOptions::backoff, 0.0, 0.3,
     "m: the human grasp centre's start beyond the SDH's, along the approach"},
    {"winding_precision_mid", &TransferOptions::winding_precision_mid, 0.0, 1e6,
     "the winding targets on the way"},
    {"winding_precision_end", &TransferOptions::winding_precision_end, 0.0, 1e6,
     "the winding targets at the end"},
    {"collision_margin", &TransferOptions::collision_margin, 0.0, 0.1,
     "m: the collision task's margin"},
    {"collision_precision", &TransferOptions::collision_precision, 0.0, 1e6, "the collision task"},
    {"approach_precision_mid", &TransferOptions::approach_precision_mid, 0.0, 1e6,
     "the SDH's approach axis along the human's, on the way"},
    {"approach_precision_end", &TransferOptions::approach_precision_end, 0.0, 1e6,
     "the SDH's approach axis along the human's, at the end"},
    {"line_precision_mid", &TransferOptions::line_precision_mid, 0.0, 1e6,
     "per m^2: the SDH's grasp centre on the human's approach line"},
    {"line_precision_end", &TransferOptions::line_precision_end, 0.0, 1e6,
     "per m^2: the same at the end"},
    {"limit_precision", &TransferOptions::limit_precision, 0.0, 1e6, "the joint-limit penalty"},
    {"final_approach", &TransferOptions::final_approach, 0.0, 1.0,
     "m: how far the planned hand may move on to touch"},
    {"fingertip_prior", &TransferOptions::fingertip_prior, 0.0, 1.0,
     "per m^2 or rad^2: the fingertip fit's pull to the transplant"},
    {"fingertip_scale", &TransferOptions::fingertip_scale, 0.0, 10.0,
     "the source tips' scale; 0 derives it (SDH: 2.175)"},
    {"transplant_opening", &TransferOptions::transplant_opening, 0.0, 1.5,
     "rad: how far the transplant opens the SDH's fingers"},
    {"virtual_finger_margin", &TransferOptions::virtual_finger_margin, 0.0, 0.2,
     "m: the virtual-finger hand's aperture beyond the source's"},
}};

/// The entry of transfer_parameters called \p name, or nullptr.
[[nodiscard]] constexpr const TransferParameter* find_transfer_parameter(
    std::string_view name) noexcept {
  for (const TransferParameter& p : transfer_parameters)
    if (p.name == name) return &p;
  return nullptr;
}

namespace detail {
// "[0, 0.3]": a parameter's range as the messages and --help print it.
inline std::string parameter_range(const TransferParameter& p) {
  char b[64];
  std::snprintf(b, sizeof b, "[%g, %g]", p.min, p.max);
  return b;
}
// Throws naming the parameter unless v is in p's range (NaN is not).
inline void check_parameter_value(const TransferParameter& p, double v) {
  if (!(v >= p.min && v <= p.max)) {
    char got[32];
    std::snprintf(got, sizeof got, "%g", v);
    throw_invalid_argument(p.name, "must be in " + parameter_range(p) + " (" +
                                       std::string(p.meaning) + "), got " + got);
  }
}
}  // namespace detail

/// Sets the parameter called \p name (one of transfer_parameters) of \p options to \p value.
/// \throws topograsp::invalid_argument naming "name" (unknown; the message lists the names) or
/// the parameter (\p value outside its range, or not finite; the message gives the range);
/// \p options is unchanged then.
inline void set_transfer_parameter(TransferOptions& options, std::string_view name, double value) {
  if (const TransferParameter* p = find_transfer_parameter(name)) {
    detail::check_parameter_value(*p, value);
    options.*(p->field) = value;
    return;
  }
  std::string names;
  for (const TransferParameter& p : transfer_parameters)
    names += (names.empty() ? "" : ", ") + std::string(p.name);
  detail::throw_invalid_argument("name", "unknown transfer parameter \"" + std::string(name) +
                                             "\" (expected one of " + names + ")");
}

/// Checks every parameter of transfer_parameters in \p options against its range.
/// \throws topograsp::invalid_argument naming the first parameter out of range.
inline void validate_transfer_parameters(const TransferOptions& options) {
  for (const TransferParameter& p : transfer_parameters)
    detail::check_parameter_value(p, options.*(p.field));
}

/// The joints hand \p M starts a transfer from: the SDH's options.sdh_preshape, any other hand's
/// zero clamped to its joint limits with its thumb turned to oppose the fingers (opposed_thumb).
template <const auto& M>
  requires HandModel<decltype(M)>
[[nodiscard]] Vec<M.nq> base_preshape(const TransferOptions& options) {
  if constexpr (M.nq == 7) {
    if (M.name.view() == models::schunk_sdh.name.view()) return options.sdh_preshape;
  }
  return opposed_thumb<M>(clamp_to_limits<M>(Vec<M.nq>::Zero()));
}

/// A grasp transferred to the SDH (HandTransfer of the SDH: its 7 joints, its two curves).
using RobotGrasp = HandTransfer<models::schunk_sdh>;

namespace detail {

using Clock = std::chrono::steady_clock;
inline double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

// The pose of the SDH's grasp centre that corresponds to the human grasp centre (object frame):
// the same point, the SDH's approach along the human's, the SDH's "up" (thumb to fingers) along
// the human's fingers (grasp_frame).
inline Eigen::Isometry3d sdh_grasp_target(const HumanGrasp& g) {
  return grasp_frame(source_grasp(g));
}

// The SDH palm (root) pose that puts its grasp centre at T (object frame).
inline Eigen::Isometry3d sdh_root_for_grasp_centre(const Eigen::Isometry3d& T) {
  return root_for_grasp_frame<models::schunk_sdh>(T, Vec<7>::Zero());
}

// The point of \p shape's surface nearest \p p (point_a, object frame), the outward normal there
// (normal) and p's signed distance (distance, negative inside): the contact of the part in which
// p lies deepest, or of the nearest part if p is outside them all.
inline Contact nearest_surface(const Composite& shape, const Vec3& p) {
  const Primitive probe = Primitive::sphere(p, 1e-6);
  Contact nearest;
  nearest.distance = std::numeric_limits<double>::infinity();
  for (const Primitive& part : shape.parts()) {
    const Contact k = signed_distance(part, probe);
    if (k.distance < nearest.distance) nearest = k;
  }
  return nearest;
}

}  // namespace detail

namespace detail {

/// Why the human grasp \p g cannot be transferred by any method (a non-finite hand pose,
/// configuration or descriptor), or empty if it can.
[[nodiscard]] inline std::string unusable_human_grasp(const HumanGrasp& g) {
  if (!g.hand_pose.matrix().allFinite()) return "the human hand pose is not finite";
  if (!g.q.allFinite()) return "the human configuration is not finite";
  if (!g.descriptor.values.allFinite()) return "the human windings are not finite";
  return {};
}

/// Why the source grasp \p g cannot be transferred (a non-finite pose or joints), or empty.
template <const auto& S>
[[nodiscard]] std::string unusable_source_grasp(const HandGrasp<S>& g) {
  if (!g.root.matrix().allFinite()) return "the source hand pose is not finite";
  if (!g.q.allFinite()) return "the source configuration is not finite";
  return {};
}

}  // namespace detail

/// \p q_hand opened until the SDH at \p root (its palm, object frame) is sim.contact_gap clear of
/// the object (open_hand_until_clear<models::schunk_sdh>): its proximal joints (fingers and thumb)
/// lowered and its distal joints raised by 0.05 rad a step, the knuckle kept.
template <class = void>
[[nodiscard]] Vec<7> open_until_clear(const GraspObject& object, const Eigen::Isometry3d& root,
                                      const Vec<7>& q_hand, const GraspSimOptions& sim) {
  return open_hand_until_clear<models::schunk_sdh>(object, root, q_hand, sim);
}

/// The SDH's joints of the transplant baseline before closing: sdh_preshape's knuckle, the
/// proximal joints of the fingers and the thumb at -options.transplant_opening, the distal ones at
/// +options.transplant_opening.
[[nodiscard]] inline Vec<7> transplant_preshape(const TransferOptions& options) {
  return opened_preshape<models::schunk_sdh>(options.transplant_opening, options.sdh_preshape);
}

/// The transplant baseline for any pair of hands: \p Target's grasp frame at the source's
/// (grasp_frame: the same point, its approach and "up" along the source's), its joints at
/// opened_preshape(options.transplant_opening, base_preshape), backed off along its approach only
/// as far as needed to clear the object, then closed until contact and judged (with \p second if
/// set). It is not moved on until contact when it is clear, as the topological method is: that
/// costs the SDH 4 of the 20 bottle grasps of seed 1 (docs/results.md), and a baseline is not
/// given a help that weakens it. Not planned (reason says why) for a source that is not finite or
/// a hand that cannot be placed clear of the object.
template <const auto& Target, const auto& Source>
  requires HandModel<decltype(Target)> && HandModel<decltype(Source)>
[[nodiscard]] HandTransfer<Target> transplant_grasp(const GraspObject& object,
                                                    const HandGrasp<Source>& source,
                                                    const TransferOptions& options = {},
                                                    const SecondJudge<Target>& second = {}) {
  const auto t0 = detail::Clock::now();
  HandTransfer<Target> r;
  r.method = TransferMethod::transplant;
  r.reason = detail::unusable_source_grasp(source);
  if (!r.reason.empty()) return r;
  const Eigen::Isometry3d target = grasp_frame(source);
  const Vec<Target.nq> preshape =
      opened_preshape<Target>(options.transplant_opening, base_preshape<Target>(options));
  const auto root =
      place_hand_at_contact<Target>(object, root_for_grasp_frame<Target>(target, preshape),
                                    preshape, target.linear().col(2), options.sim);
  r.plan_ms = detail::ms_since(t0);
  if (!root) {
    r.reason = "the hand cannot be placed clear of the object";
    return r;
  }
  r.reason = unusable_hand_pose<Target>(*root, preshape);
  if (!r.reason.empty()) return r;
  r.planned = true;
  simulate_hand_grasp<Target>(object, *root, preshape, options.sim, second, r);
  return r;
}

/// The largest distance (m) between a fitted fingertip and its target for which the fingertip
/// mapping counts as done: 0.5 m, about three times the SDH's finger length (0.17 m). A larger
/// error means the targets were out of the hand's reach, and the fit failed.
inline constexpr double k_fingertip_max_error = 0.5;

/// The finger correspondence of the fingertip mapping from hand \p Source to hand \p Target: for
/// each finger of Target (its hand description's order), the finger of Source whose tip its tip is
/// fitted to, or -1. The thumb goes to the thumb; Target's other fingers, the j-th of its n in
/// order, to the floor(j m / n)-th of Source's m other fingers, each Source finger used once (a
/// Target finger whose Source finger is already taken is left out of the fit and closes with the
/// hand). From the human hand (index, middle, ring, little): the SDH's and the Barrett's two
/// fingers get the index and the ring; the Allegro's and the LEAP hand's three the index, middle
/// and ring; the Shadow hand's four their namesakes. The rule was stated before any run.
template <const auto& Target, const auto& Source>
  requires HandModel<decltype(Target)> && HandModel<decltype(Source)>
[[nodiscard]] constexpr std::array<int, Target.fingers.size()> fingertip_correspondence() {
  constexpr int n = static_cast<int>(Target.fingers.size()) - 1;
  constexpr int m = static_cast<int>(Source.fingers.size()) - 1;
  std::array<int, Source.fingers.size() - 1> source_other{};
  for (int f = 0, k = 0; f <= m; ++f)
    if (f != Source.thumb) source_other[static_cast<std::size_t>(k++)] = f;
  std::array<int, Target.fingers.size()> c{};
  int j = 0, last = -1;
  for (int f = 0; f <= n; ++f) {
    auto& to = c[static_cast<std::size_t>(f)];
    if (f == Target.thumb) {
      to = Source.thumb;
      continue;
    }
    const int k = j++ * m / n;
    to = k == last ? -1 : source_other[static_cast<std::size_t>(k)];
    last = k;
  }
  return c;
}

/// How many fingertips the fingertip mapping from \p Source to \p Target fits: the thumb and
/// min(n, m) others.
template <const auto& Target, const auto& Source>
inline constexpr int fingertip_count =
    1 + static_cast<int>(std::min(Target.fingers.size(), Source.fingers.size())) - 1;

namespace detail {

// The fitted pairs of the fingertip mapping (fingertip_correspondence): {Target finger, Source
// finger}, the thumb first, then Target's fingers in order.
template <const auto& Target, const auto& Source>
constexpr std::array<std::pair<int, int>, fingertip_count<Target, Source>> fingertip_pairs() {
  constexpr auto c = fingertip_correspondence<Target, Source>();
  std::array<std::pair<int, int>, fingertip_count<Target, Source>> pairs{};
  pairs[0] = {Target.thumb, Source.thumb};
  std::size_t k = 1;
  for (int f = 0; f < static_cast<int>(c.size()); ++f)
    if (f != Target.thumb && c[static_cast<std::size_t>(f)] >= 0)
      pairs[k++] = {f, c[static_cast<std::size_t>(f)]};
  return pairs;
}

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

// The radius (m) of finger f's tip: of the shapes of its tip's link, the one nearest the tip
// point; its radius (sphere, capsule, cylinder) or smallest half extent (box). 0 if the link has
// no shape.
template <const auto& M>
double tip_radius(int f) {
  KinematicsData<M> d;
  forward_kinematics(d, Vec<M.nq>::Zero());
  const LinkPoint tip = finger_tip<M>(f);
  const Primitive probe = Primitive::sphere(world_point(d, tip), 1e-6);
  double nearest = std::numeric_limits<double>::infinity(), radius = 0.0;
  for (std::size_t k = 0; k < M.n_shapes; ++k) {
    const Shape& s = M.shapes[k];
    if (s.link != tip.link) continue;
    const double distance = std::abs(signed_distance(world_shape(d, k), probe).distance);
    if (distance >= nearest) continue;
    nearest = distance;
    const auto& size = s.spec.size;
    radius = s.spec.type == ShapeType::box ? std::min({size[0], size[1], size[2]}) : size[0];
  }
  return radius;
}

// Hand M's opposition at kinematics d mapped by T: its thumb tip (the first virtual finger) and
// the centroid of its other fingertips (the second).
template <const auto& M>
std::pair<Vec3, Vec3> opposition(const KinematicsData<M>& d,
                                 const Eigen::Isometry3d& T = Eigen::Isometry3d::Identity()) {
  Vec3 fingers = Vec3::Zero();
  for (int f = 0; f < static_cast<int>(M.fingers.size()); ++f)
    if (f != M.thumb) fingers += T * world_point(d, finger_tip<M>(f));
  fingers /= static_cast<double>(M.fingers.size() - 1);
  return {T * world_point(d, finger_tip<M>(M.thumb)), fingers};
}

// Hand M's free-base configuration (FreeBase) with its grasp frame (hand_profile) at T (object
// frame, grasp_frame's convention: z the approach, x up) and joints q.
template <const auto& M>
Vec<FreeBase<M>::model.nq> free_at_grasp_frame(const Eigen::Isometry3d& T, const Vec<M.nq>& q) {
  constexpr auto& F = FreeBase<M>::model;
  const HandProfile<M> profile = hand_profile<M>();
  Eigen::Isometry3d frame = T;
  frame.linear() =
      T.linear() * palm_rotation(profile.axes, gripper_hand_axes.approach, gripper_hand_axes.up);
  return place_frame<F>(
      frame, F.find_frame(M.frames[static_cast<std::size_t>(profile.frame)].spec.name.view()), q);
}

// The baselines' last steps for hand M: q opened until M at root (object frame) is clear of the
// object (open_hand_until_clear), moved on along its approach until contact (at most
// final_approach) or backed off if it still overlaps (place_hand_at_contact), then closed and
// judged into r (planned; r.reason kept; with second if set) with r.plan_ms the time since t0. If
// it cannot be placed nothing is simulated and r.reason says why.
template <const auto& M>
void open_place_and_simulate(const GraspObject& object, const Eigen::Isometry3d& root,
                             const Vec<M.nq>& q, const TransferOptions& options,
                             const SecondJudge<M>& second, Clock::time_point t0,
                             HandTransfer<M>& r) {
  const Vec<M.nq> opened = open_hand_until_clear<M>(object, root, q, options.sim);
  const Vec3 approach = root.linear() * grasp_approach<M>(opened);
  const auto placed =
      place_hand_at_contact<M>(object, root, opened, approach, options.sim, options.final_approach);
  r.plan_ms = ms_since(t0);
  if (!placed) {
    r.reason = "the hand cannot be placed clear of the object";
    return;
  }
  const std::string unusable = unusable_hand_pose<M>(*placed, opened);
  if (!unusable.empty()) {
    r.reason = unusable;
    return;
  }
  r.planned = true;
  simulate_hand_grasp<M>(object, *placed, opened, options.sim, second, r);
}

}  // namespace detail

/// The size of hand \p Target over hand \p Source for the fingertip mapping: the summed lengths of
/// the fitted digits held straight (fingertip_correspondence; a digit from the first link that
/// moves it alone out to its tip). Human -> SDH: 0.5145 / 0.2366 = 2.175.
template <const auto& Target, const auto& Source>
[[nodiscard]] double fingertip_scale() {
  double target = 0.0, source = 0.0;
  for (const auto& [t, s] : detail::fingertip_pairs<Target, Source>()) {
    target += detail::digit_length<Target>(t);
    source += detail::digit_length<Source>(s);
  }
  return target / source;
}

/// The targets of the fingertip mapping (object frame), the thumb's first, then Target's fitted
/// fingers in order (fingertip_correspondence): the tips of their Source fingers in \p source
/// scaled about their centroid by options.fingertip_scale (0: fingertip_scale<Target, Source>()),
/// then each moved to the nearest point of the object's surface and out along its normal by the
/// radius of Target's fingertip and options.sim.contact_gap, so that the fitted tips touch the
/// object, not the air. A scaled tip farther than k_fingertip_max_error from the centroid (a scale
/// far beyond any hand's, or one that overflows) is left where it is, for the fit to refuse.
template <const auto& Target, const auto& Source>
  requires HandModel<decltype(Target)> && HandModel<decltype(Source)>
[[nodiscard]] std::array<Vec3, fingertip_count<Target, Source>> fingertip_targets(
    const GraspObject& object, const HandGrasp<Source>& source,
    const TransferOptions& options = {}) {
  constexpr auto pairs = detail::fingertip_pairs<Target, Source>();
  KinematicsData<Source> sd;
  forward_kinematics(sd, source.q);
  std::array<Vec3, pairs.size()> goal;
  Vec3 centroid = Vec3::Zero();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    goal[k] = source.root * world_point(sd, finger_tip<Source>(pairs[k].second));
    centroid += goal[k];
  }
  centroid /= static_cast<double>(pairs.size());
  const double scale =
      options.fingertip_scale > 0.0 ? options.fingertip_scale : fingertip_scale<Target, Source>();
  const Composite shape = object.composite();  // parts() views it: keep it alive
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    Vec3& p = goal[k];
    p = centroid + scale * (p - centroid);
    if (!p.allFinite() || (p - centroid).norm() > k_fingertip_max_error) continue;
    const Contact c = detail::nearest_surface(shape, p);
    p = c.point_a +
        (detail::tip_radius<Target>(pairs[k].first) + options.sim.contact_gap) * c.normal;
  }
  return goal;
}

/// Fingertip mapping (Rohling and Hollerbach 1993) from any hand to any hand: Target's fingertips
/// (fingertip_correspondence: the thumb to the thumb, the fingers spread over the source's) fitted
/// to fingertip_targets, the source's tips scaled to Target's size and put on the object's
/// surface. Target on its free base is fitted by damped least squares, within its joint limits,
/// started at the transplant pose (its grasp frame at the source's, joints base_preshape) with a
/// weak pull toward it (options.fingertip_prior); then opened until clear of the object
/// (open_hand_until_clear), backed off along its approach only if it still overlaps, or moved on
/// until contact (at most final_approach), closed until contact and judged (with \p second if
/// set).
///
/// When the fit cannot be done the result is not planned (planned false, nothing simulated) and
/// reason says why: a non-finite source grasp, a fit whose cost is not finite (fingertip targets so
/// far apart that their squared errors overflow, e.g. fingertip_scale = 1e300), a fit whose
/// fingertips end more than k_fingertip_max_error from their targets (targets out of the hand's
/// reach, e.g. fingertip_scale = 1e10), or a fitted hand that HandScene cannot take. It never
/// reports the transplant pose it starts from as a fingertip transfer.
template <const auto& Target, const auto& Source>
  requires HandModel<decltype(Target)> && HandModel<decltype(Source)>
[[nodiscard]] HandTransfer<Target> fingertip_grasp(const GraspObject& object,
                                                   const HandGrasp<Source>& source,
                                                   const TransferOptions& options = {},
                                                   const SecondJudge<Target>& second = {}) {
  const auto t0 = detail::Clock::now();
  HandTransfer<Target> r;
  r.method = TransferMethod::fingertip;
  r.reason = detail::unusable_source_grasp(source);
  if (!r.reason.empty()) return r;
  constexpr auto& F = FreeBase<Target>::model;
  constexpr auto pairs = detail::fingertip_pairs<Target, Source>();
  constexpr int n = static_cast<int>(pairs.size());
  constexpr int rows = 3 * n + F.nq;
  const auto goal = fingertip_targets<Target>(object, source, options);
  const double scale =
      options.fingertip_scale > 0.0 ? options.fingertip_scale : fingertip_scale<Target, Source>();
  Vec<F.nq> q =
      detail::free_at_grasp_frame<Target>(grasp_frame(source), base_preshape<Target>(options));
  const Vec<F.nq> lo = lower_limits<F>(), hi = upper_limits<F>();
  // Residual: the tip errors (m), then a weak pull toward the transplant pose and the pre-shape
  // (weight options.fingertip_prior per m or rad), which keeps the under-determined fit (more
  // unknowns than equations) from drifting.
  const Vec<F.nq> q_ref = q;
  const double w = std::sqrt(options.fingertip_prior);
  KinematicsData<F> d;
  const auto tip = [&](int k) { return finger_tip<F>(pairs[static_cast<std::size_t>(k)].first); };
  const auto residual = [&](const Vec<F.nq>& x, Vec<rows>& e) {
    forward_kinematics(d, x);
    for (int k = 0; k < n; ++k)
      e.template segment<3>(3 * k) = world_point(d, tip(k)) - goal[static_cast<std::size_t>(k)];
    e.template tail<F.nq>() = w * (x - q_ref);
    return e.squaredNorm();
  };
  Vec<rows> e;
  double cost = residual(q, e);
  if (!std::isfinite(cost)) {
    r.plan_ms = detail::ms_since(t0);
    char buf[128];
    std::snprintf(buf, sizeof buf,
                  "the fingertip fit's cost is not finite (fingertip targets out of range, "
                  "scale %g)",
                  scale);
    r.reason = buf;
    return r;
  }
  double lambda = 1e-3;
  Mat<rows, F.nq> J = Mat<rows, F.nq>::Zero();
  J.template bottomRows<F.nq>() = w * Mat<F.nq, F.nq>::Identity();
  bool progressed = false;  // a step was accepted: the fit left the transplant pose
  for (int it = 0; it < options.fingertip_iterations; ++it) {
    for (int k = 0; k < n; ++k)
      J.template middleRows<3>(3 * k) = point_jacobian(d, tip(k).link, world_point(d, tip(k)));
    const Mat<F.nq, F.nq> H = J.transpose() * J + lambda * Mat<F.nq, F.nq>::Identity();
    const Vec<F.nq> trial = (q - H.ldlt().solve(J.transpose() * e)).cwiseMax(lo).cwiseMin(hi);
    Vec<rows> et;
    const double c = residual(trial, et);
    if (c < cost) {
      const bool settled = cost - c < 1e-12;
      progressed = true;
      q = trial;
      e = et;
      cost = c;
      lambda = std::max(lambda / 3.0, 1e-9);
      if (settled) break;
    } else {
      lambda *= 10.0;
      (void)residual(q, e);  // restore the kinematics of q
    }
  }
  if (!progressed) {
    r.plan_ms = detail::ms_since(t0);
    r.reason = "the fingertip fit accepted no step (the hand would stay at the transplant pose)";
    return r;
  }
  forward_kinematics(d, q);
  double tip_error = 0.0;
  for (int k = 0; k < n; ++k)
    tip_error =
        std::max(tip_error, (world_point(d, tip(k)) - goal[static_cast<std::size_t>(k)]).norm());
  if (!(tip_error <= k_fingertip_max_error)) {
    r.plan_ms = detail::ms_since(t0);
    char buf[128];
    std::snprintf(buf, sizeof buf,
                  "the fingertip fit did not reach the targets (largest tip error %g m, more "
                  "than %g m)",
                  tip_error, k_fingertip_max_error);
    r.reason = buf;
    return r;
  }
  const Eigen::Isometry3d fitted = link_pose(d, F.find_link(Target.links[0].spec.name.view()));
  const Vec<Target.nq> q_hand = q.template tail<Target.nq>();
  r.reason = unusable_hand_pose<Target>(fitted, q_hand);
  if (!r.reason.empty()) {
    r.plan_ms = detail::ms_since(t0);
    r.reason = "fitted: " + r.reason;
    return r;
  }
  detail::open_place_and_simulate<Target>(object, fitted, q_hand, options, second, t0, r);
  return r;
}

namespace detail {

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
/// Not planned (planned false, reason says why) for a non-finite source grasp, a pad opposition
/// shorter than 1 mm or along the source's approach (no axis to turn the hand by), or a hand that
/// cannot be placed clear of the object.
template <const auto& Target, const auto& Source>
  requires HandModel<decltype(Target)> && HandModel<decltype(Source)>
[[nodiscard]] HandTransfer<Target> virtual_finger_grasp(const GraspObject& object,
                                                        const HandGrasp<Source>& source,
                                                        const TransferOptions& options = {},
                                                        const SecondJudge<Target>& second = {}) {
  const auto t0 = detail::Clock::now();
  HandTransfer<Target> r;
  r.method = TransferMethod::virtual_finger;
  r.reason = detail::unusable_source_grasp(source);
  if (!r.reason.empty()) return r;
  KinematicsData<Source> sd;
  forward_kinematics(sd, source.q);
  const auto [thumb_s, fingers_s] = detail::opposition<Source>(sd, source.root);
  const Composite shape = object.composite();  // parts() views it: keep it alive
  // Palm opposition when the palm touches the object (within the approach's contact gap and the
  // stability suite's touch distance), pad opposition when only the digits do.
  const Composite in_hand = object.composite(source.root.inverse());
  double palm_distance = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < Source.n_shapes; ++k)
    if (Source.shapes[k].link == Source.palm.link)
      for (const Primitive& part : in_hand.parts())
        palm_distance = std::min(palm_distance, signed_distance(world_shape(sd, k), part).distance);
  const bool pad =
      !(palm_distance <= options.sim.contact_gap + options.sim.stability.touch_distance);
  const Eigen::Isometry3d target = grasp_frame(source);
  const Vec3 approach = target.linear().col(2);
  const Vec3 opposition = pad ? Vec3(fingers_s - thumb_s) : Vec3(target.linear().col(0));
  const double aperture =
      pad ? opposition.norm() : detail::chord_length(shape, target.translation(), opposition);
  if (pad && (!(aperture >= 1e-3) || opposition.cross(approach).norm() < 1e-3 * aperture)) {
    r.plan_ms = detail::ms_since(t0);
    r.reason = "the source's opposition is too short or along its approach";
    return r;
  }
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
  r.reason = pad ? "pad opposition" : "palm opposition";
  detail::open_place_and_simulate<Target>(object, root, preshape, options, second, t0, r);
  return r;
}

namespace detail {

// The SDH baseline \p run on the human grasp g, judged also by options.sim.second_judge_sdh; a
// non-finite human grasp (its descriptor too) is not planned, reason says why.
template <class Run>
RobotGrasp sdh_from_human(TransferMethod method, const HumanGrasp& g,
                          const TransferOptions& options, Run run) {
  if (std::string problem = unusable_human_grasp(g); !problem.empty()) {
    RobotGrasp r;
    r.method = method;
    r.reason = std::move(problem);
    return r;
  }
  return run(source_grasp(g), options.sim.second_judge_sdh);
}

}  // namespace detail

/// The paper's baseline on the SDH (transplant_grasp from the human hand), judged also by
/// options.sim.second_judge_sdh.
template <class = void>
[[nodiscard]] RobotGrasp transfer_transplant(const GraspObject& object, const HumanGrasp& g,
                                             const TransferOptions& options = {}) {
  return detail::sdh_from_human(TransferMethod::transplant, g, options, [&](auto s, auto& second) {
    return transplant_grasp<models::schunk_sdh>(object, s, options, second);
  });
}

/// The fingertip mapping of Table I: the human grasp \p g to the SDH (fingertip_grasp: the human's
/// thumb, index and ring tips onto the SDH's thumb, finger 1 and finger 2 tips), judged also by
/// options.sim.second_judge_sdh.
template <class = void>
[[nodiscard]] RobotGrasp transfer_fingertip(const GraspObject& object, const HumanGrasp& g,
                                            const TransferOptions& options = {}) {
  return detail::sdh_from_human(TransferMethod::fingertip, g, options, [&](auto s, auto& second) {
    return fingertip_grasp<models::schunk_sdh>(object, s, options, second);
  });
}

/// The fingertip targets of transfer_fingertip (fingertip_targets), the SDH's thumb tip's first.
template <class = void>
[[nodiscard]] std::array<Vec3, 3> fingertip_targets(const GraspObject& object, const HumanGrasp& g,
                                                    const TransferOptions& options = {}) {
  return fingertip_targets<models::schunk_sdh>(object, source_grasp(g), options);
}

/// The virtual-finger mapping of Table I: the human grasp \p g to the SDH (virtual_finger_grasp:
/// the SDH's thumb opposes the midpoint of its two finger tips), judged also by
/// options.sim.second_judge_sdh.
template <class = void>
[[nodiscard]] RobotGrasp transfer_virtual_finger(const GraspObject& object, const HumanGrasp& g,
                                                 const TransferOptions& options = {}) {
  return detail::sdh_from_human(
      TransferMethod::virtual_finger, g, options, [&](auto s, auto& second) {
        return virtual_finger_grasp<models::schunk_sdh>(object, s, options, second);
      });
}

/// The point (object frame) that the windings of a topological transfer are taken around: the
/// centre of mass, or the point of \p object nearest \p grasp_centre, the source hand's grasp
/// centre (the grasp centre itself if it lies inside the object).
[[nodiscard]] inline Vec3 winding_reference_point(const GraspObject& object,
                                                  const Vec3& grasp_centre,
                                                  WindingReference reference) {
  if (reference == WindingReference::centre_of_mass) return object.centre_of_mass();
  const Contact nearest = detail::nearest_surface(object.composite(), grasp_centre);
  return nearest.distance > 0.0 ? nearest.point_a : grasp_centre;
}

/// The same for the human grasp \p g (its grasp centre).
[[nodiscard]] inline Vec3 winding_reference_point(const GraspObject& object, const HumanGrasp& g,
                                                  WindingReference reference) {
  return winding_reference_point(object, detail::sdh_grasp_target(g).translation(), reference);
}

/// The human's descriptor y of \p g around \p p (object frame): its two largest windings.
template <class = void>
[[nodiscard]] WindingDescriptor human_descriptor(const HumanGrasp& g, const Vec3& p) {
  KinematicsData<models::human_hand> d;
  forward_kinematics(d, g.q);
  return winding_descriptor(d, Vec3(g.hand_pose.inverse() * p));
}

/// The task set of the topological method for hand-on-arm model \p A (OnArm): the windings of the
/// hand's curves around a point (interpolated from the start to the targets), the collision
/// potential against the object, the approach axis of the hand's grasp frame, the joint limits,
/// and the grasp frame on the source's approach line.
template <const auto& A>
using ArmTopologicalTasks =
    TaskSet<WindingTask<A>, CollisionTask<A>, AxisTask<A>, JointLimitTask<A>, LineTask<A>>;

/// Builds the topological task set of hand \p M on the arm (OnArm<M>) for an object at
/// \p T_world_object whose source descriptor is \p y around \p reference (object frame), with the
/// approach of M's grasp frame (hand_profile) to be along \p approach (world) on the line through
/// \p grasp_point (world: the source's grasp centre); \p d holds the kinematics of the start
/// configuration (the winding targets start from its values).
template <const auto& M>
  requires HandModel<decltype(M)>
[[nodiscard]] ArmTopologicalTasks<OnArm<M>::model> topological_tasks(
    const GraspObject& object, const Eigen::Isometry3d& T_world_object,
    const Vec<hand_curve_count<M>>& y, const Vec3& reference, const Vec3& grasp_point,
    const Vec3& approach, const KinematicsData<OnArm<M>::model>& d,
    const TransferOptions& options) {
  constexpr auto& A = OnArm<M>::model;
  constexpr int K = hand_curve_count<M>;
  const HandProfile<M> profile = hand_profile<M>();
  const int frame =
      A.find_frame(M.frames[static_cast<std::size_t>(profile.frame)].spec.name.view());
  WindingTask<A> winding(T_world_object * reference);
  const Vec<K> w0 = winding.value(d);
  return make_task_set(
      scheduled(std::move(winding), interpolated_target<K>(w0, y),
                precision(options.winding_precision_mid, options.winding_precision_end)),
      scheduled(CollisionTask<A>(object.composite(T_world_object), options.collision_margin),
                constant_target<1>(Vec<1>::Zero()),
                constant_precision(options.collision_precision)),
      scheduled(AxisTask<A>(frame, profile.axes.approach),
                constant_target<3>(approach.normalized()),
                precision(options.approach_precision_mid, options.approach_precision_end)),
      scheduled(JointLimitTask<A>(), constant_target<A.nq>(Vec<A.nq>::Zero()),
                constant_precision(options.limit_precision)),
      scheduled(LineTask<A>(frame, grasp_point, approach), constant_target<2>(Vec2::Zero()),
                precision(options.line_precision_mid, options.line_precision_end)));
}

namespace detail {

// Solves nothing: records the solved \p plan of \p problem (whose first task is the winding task)
// into \p out: its sweeps, its termination as the reason, the windings of each step and their
// targets. False, and the reason says so, if the plan accepted no sweep (whatever ended it:
// non-finite values, too many rejections): the start held still is no work of the method; it is
// reported, never the start pose.
template <class Problem, class Plan, class Out>
bool record_plan(const Problem& problem, const Plan& plan, Out& out) {
  out.sweeps = plan.sweeps;
  out.reason = std::string(to_string(plan.termination));
  out.sweep_log = plan.sweep_log;
  out.winding_plan.clear();
  out.winding_targets.clear();
  const auto& windings = problem.stack().template get<0>();
  typename Problem::Kinematics dt;
  for (std::size_t t = 0; t < plan.q.size(); ++t) {
    forward_kinematics(dt, plan.q[t]);
    out.winding_plan.push_back(windings.task.value(dt));
    out.winding_targets.push_back(windings.target.at(static_cast<int>(t), problem.steps()));
  }
  const bool moved = std::any_of(plan.sweep_log.begin(), plan.sweep_log.end(),
                                 [](const AicoSweepRecord& s) { return s.accepted; });
  if (!moved) out.reason = "the plan failed before any progress (" + out.reason + ")";
  return moved;
}

}  // namespace detail

namespace detail {

// The topological method for hand M on the arm (OnArm<M>), the source's grasp frame
// source_frame (object frame) and descriptor y around reference (object frame) given: the object
// placed (turned) so that the source's grasp frame maps onto M's at the ready pose
// (options.arm_ready, base_preshape), pushed out by the backoff; AICO plans arm and hand with
// topological_tasks; the final hand, without the arm, moves on along its approach until contact,
// closes until contact and is judged (with second if set). With options.closing_corrections the
// targets are corrected by the windings that closing leaves and the plan made again (the plan
// whose closed windings come nearest y is kept). t0: when the transfer started.
template <const auto& M>
HandTransfer<M> topological_on_arm(const GraspObject& object, const Eigen::Isometry3d& source_frame,
                                   const Vec<hand_curve_count<M>>& y, const Vec3& reference,
                                   const TransferOptions& options, const SecondJudge<M>& second,
                                   Clock::time_point t0) {
  constexpr auto& A = OnArm<M>::model;
  constexpr int K = hand_curve_count<M>;
  HandTransfer<M> r;
  r.method = TransferMethod::topological;
  Vec<A.nq> q0;
  q0 << options.arm_ready, base_preshape<M>(options);
  KinematicsData<A> d;
  forward_kinematics(d, q0);
  const HandProfile<M> profile = hand_profile<M>();
  Eigen::Isometry3d gc = frame_pose(
      d, A.find_frame(M.frames[static_cast<std::size_t>(profile.frame)].spec.name.view()));
  gc.linear() =
      gc.linear() * palm_rotation(profile.axes, gripper_hand_axes.approach, gripper_hand_axes.up);
  const Vec3 approach = gc.linear().col(2);
  // The object such that the source's grasp frame maps onto the hand's, pushed out by the backoff.
  const Eigen::Isometry3d source_centre =
      Eigen::Translation3d(options.backoff * approach) * gc;  // world
  const Eigen::Isometry3d T_world_object = source_centre * source_frame.inverse();
  constexpr int root_link = A.find_link(M.links[0].spec.name.view());
  // One plan toward the winding targets `target`: fills out's plan records, and its hand_pose and
  // q_open with the placed hand; false (out.reason says why) if it cannot be placed.
  const auto plan_for = [&](const Vec<K>& target, HandTransfer<M>& out) {
    AicoProblem<A, ArmTopologicalTasks<A>> problem(
        topological_tasks<M>(object, T_world_object, target, reference, source_centre.translation(),
                             approach, d, options),
        q0, options.aico);
    AicoWorkspace ws(problem);
    const AicoResult<A.nq> plan = solve(problem, ws);
    if (!record_plan(problem, plan, out)) return false;
    KinematicsData<A> dt;
    forward_kinematics(dt, plan.q.back());
    const Eigen::Isometry3d root = T_world_object.inverse() * link_pose(dt, root_link);
    const Vec<M.nq> q_hand = clamp_to_limits<M>(Vec<M.nq>(plan.q.back().template tail<M.nq>()));
    const auto cleared =
        place_hand_at_contact<M>(object, root, q_hand, root.linear() * grasp_approach<M>(q_hand),
                                 options.sim, options.final_approach);
    if (!cleared) {
      out.reason = "the planned hand penetrates the object";
      return false;
    }
    const std::string unusable = unusable_hand_pose<M>(*cleared, q_hand);
    if (!unusable.empty()) {
      out.reason = unusable;
      return false;
    }
    out.hand_pose = *cleared;
    out.q_open = q_hand;
    return true;
  };
  r.source_winding = y;
  const bool placed = plan_for(y, r);
  if (placed && options.closing_corrections > 0) {
    const auto closed_windings = [&](const HandTransfer<M>& c) {
      auto scene = hand_scene<M>(object, c.hand_pose, c.q_open, options.sim);
      return hand_windings<M>(reference, c.hand_pose,
                              close_hand(scene, options.sim.close).q_closed);
    };
    Vec<K> w = closed_windings(r);
    double error = (w - y).norm();
    Vec<K> target = y;
    for (int k = 0; k < options.closing_corrections; ++k) {
      target = (target + (y - w)).cwiseMax(0.0);
      HandTransfer<M> c;
      c.method = r.method;
      c.source_winding = y;
      if (!plan_for(target, c)) break;
      w = closed_windings(c);
      if ((w - y).norm() < error) {
        error = (w - y).norm();
        r = std::move(c);
      }
    }
  }
  r.plan_ms = ms_since(t0);
  if (!placed) return r;
  r.planned = true;
  const Eigen::Isometry3d hand = r.hand_pose;
  const Vec<M.nq> q_open = r.q_open;
  simulate_hand_grasp<M>(object, hand, q_open, options.sim, second, r);
  if (options.winding_reference != WindingReference::centre_of_mass)
    r.winding = hand_windings<M>(reference, hand, r.q_closed);
  return r;
}

}  // namespace detail

/// Topological synergies (the paper): the human's descriptor y (its two largest windings around
/// the object's centre of mass) becomes the winding target of the SDH's two curves; AICO plans the
/// 14-DOF arm + SDH from its ready pose with the collision task, the approach direction and (our
/// addition, docs/transfer.md) the grasp centre on the human's approach line; the object is placed
/// (turned) so that the human's approach is the SDH's at the ready pose, a little out of reach.
/// The final hand, without the arm, moves on along its approach until contact, is closed until
/// contact and shaken (detail::topological_on_arm, which any hand on the arm shares:
/// transfer_hand_on_arm).
template <class = void>
[[nodiscard]] RobotGrasp transfer_topological(const GraspObject& object, const HumanGrasp& g,
                                              const TransferOptions& options = {}) {
  const auto t0 = detail::Clock::now();
  if (std::string problem = detail::unusable_human_grasp(g); !problem.empty()) {
    RobotGrasp r;
    r.method = TransferMethod::topological;
    r.reason = std::move(problem);
    return r;
  }
  const Vec3 reference = winding_reference_point(object, g, options.winding_reference);
  const Vec2 y = options.winding_reference == WindingReference::centre_of_mass
                     ? g.descriptor.values
                     : human_descriptor(g, reference).values;
  return detail::topological_on_arm<models::schunk_sdh>(
      object, detail::sdh_grasp_target(g), y, reference, options, options.sim.second_judge_sdh, t0);
}

/// \p options as the topological variant \p method runs with (see TransferMethod): the paper's
/// method switches the line task and the final approach off (line_precision_mid/_end and
/// final_approach 0), paper_line only the final approach, paper_approach only the line task;
/// no_windings sets both winding precisions to 0; nearest_point the nearest-point winding
/// reference; closed_windings two closing corrections. topological and the other methods take
/// \p options as given.
[[nodiscard]] inline TransferOptions transfer_method_options(TransferMethod method,
                                                             TransferOptions options) {
  const bool no_line = method == TransferMethod::paper || method == TransferMethod::paper_approach;
  const bool no_approach = method == TransferMethod::paper || method == TransferMethod::paper_line;
  if (no_line) options.line_precision_mid = options.line_precision_end = 0.0;
  if (no_approach) options.final_approach = 0.0;
  if (method == TransferMethod::no_windings)
    options.winding_precision_mid = options.winding_precision_end = 0.0;
  if (method == TransferMethod::nearest_point)
    options.winding_reference = WindingReference::nearest_point;
  if (method == TransferMethod::closed_windings) options.closing_corrections = 2;
  return options;
}

/// Runs \p method on the human grasp \p g (a topological variant with
/// transfer_method_options); the result's method is \p method.
template <class = void>
[[nodiscard]] RobotGrasp transfer(TransferMethod method, const GraspObject& object,
                                  const HumanGrasp& g, const TransferOptions& options) {
  switch (method) {
    case TransferMethod::transplant:
      return transfer_transplant(object, g, options);
    case TransferMethod::fingertip:
      return transfer_fingertip(object, g, options);
    case TransferMethod::virtual_finger:
      return transfer_virtual_finger(object, g, options);
    default:
      break;
  }
  RobotGrasp r = transfer_topological(object, g, transfer_method_options(method, options));
  r.method = method;
  return r;
}

}  // namespace topograsp
