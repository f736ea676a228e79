// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Any hand in a transfer: HandProfile (the frame a hand grasps with, which way it approaches,
/// which way its joints open), HandTransfer (a transferred grasp of any hand model) and the steps
/// every transfer method ends with, for any hand model: open until clear of the object, move to
/// contact, close with the motors and judge with the stability suite. Every transfer method
/// (grasp/transfer/) ends through these functions.
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/aico/result.hpp>
#include <topograsp/grasp/human_grasps.hpp>
#include <topograsp/grasp/transfer_method.hpp>
#include <topograsp/model/compose.hpp>
#include <topograsp/model/models.hpp>

namespace topograsp {

/// The model of hand \p M on a free 6-DOF base (on_free_base): models::schunk_sdh_free,
/// human_hand_free and barrett_bh8_free for the shipped hands that have one, a model made once
/// for any other hand.
template <const auto& M>
struct FreeBase {
  static constexpr auto model = on_free_base(M);
};
template <>
struct FreeBase<models::schunk_sdh> {
  static constexpr const auto& model = models::schunk_sdh_free;
};
template <>
struct FreeBase<models::human_hand> {
  static constexpr const auto& model = models::human_hand_free;
};
template <>
struct FreeBase<models::barrett_bh8> {
  static constexpr const auto& model = models::barrett_bh8_free;
};

/// Hand \p M on the Schunk arm's flange, its root link at the flange (attach): the paper's
/// models::schunk_arm_sdh for the SDH, a model made once for any other hand. Its configuration is
/// the arm's 7 joints, then the hand's.
template <const auto& M>
struct OnArm {
  static constexpr auto model = attach(models::schunk_arm, "flange", M, {}, "schunk_arm_hand");
};
template <>
struct OnArm<models::schunk_sdh> {
  static constexpr const auto& model = models::schunk_arm_sdh;
};

/// How a transfer places and opens hand \p M: the frame it grasps with and the axes of that frame
/// (HandAxes: the approach and "up"), and for each joint which way opens it (-1, 0 or +1 per rad).
template <const auto& M>
struct HandProfile {
  int frame = -1;       ///< index of the grasp frame in M's frames
  HandAxes axes{};      ///< the approach and "up" in that frame
  Vec<M.nq> opening{};  ///< per joint: -1, 0 (kept) or +1, the way that opens the hand
};

namespace detail {
template <const auto& M>
consteval int palm_frame_of() {
  const int f = M.find_frame(M.palm_name.view());
  if (f < 0) detail::model_error("the hand's palm centre must be a frame to place the hand by it");
  return f;
}
}  // namespace detail

/// The profile of hand \p M (the rule is documented in docs/transfer.md, "Any hand"):
/// - the human hand: its frame "grasp_centre", human_hand_axes (the palm normal, the fingers);
/// - the SDH: its frame "grasp_centre", gripper_hand_axes (its fingers' direction, thumb to
///   fingers); its proximal joints open by lowering, its distal joints by raising (the tips kept
///   pointing inward, the paper's pre-shapes), the knuckle kept;
/// - any other hand (the Barrett, the imported hands, a user's): its palm-centre frame with
///   approach +z (out of the palm, toward the object) and up +y (from the thumb toward the
///   fingers, or along them), the convention of docs/models.md for a hand description.
/// Every hand but the SDH opens against its closing directions (-closing_directions<M>()).
template <const auto& M>
  requires HandModel<decltype(M)>
[[nodiscard]] HandProfile<M> hand_profile() {
  HandProfile<M> p;
  p.opening = -closing_directions<M>();
  const std::string_view name = M.name.view();
  if (name == "human_hand") {
    p.frame = M.find_frame("grasp_centre");
    p.axes = human_hand_axes;
  } else if (name == "schunk_sdh") {
    p.frame = M.find_frame("grasp_centre");
    p.axes = gripper_hand_axes;
    p.opening = (Vec<M.nq>() << 0, -1, 1, -1, 1, -1, 1).finished();
  } else {
    p.frame = detail::palm_frame_of<M>();
    p.axes = HandAxes{Vec3::UnitZ(), Vec3::UnitY()};
  }
  return p;
}

/// The joints of hand \p M opened by \p opening rad from \p base: each joint that opens
/// (hand_profile's opening) set to opening times its opening direction, the others kept as in
/// \p base; then clamped to the joint limits. For the SDH with base sdh_preshape this is the
/// transplant baseline's pre-shape (transplant_preshape).
template <const auto& M>
  requires HandModel<decltype(M)>
[[nodiscard]] Vec<M.nq> opened_preshape(double opening, const Vec<M.nq>& base) {
  const Vec<M.nq> dir = hand_profile<M>().opening;
  Vec<M.nq> q = base;
  for (int i = 0; i < M.nq; ++i)
    if (dir[i] != 0.0) q[i] = opening * dir[i];
  return clamp_to_limits<M>(q);
}

/// The tip of finger \p f of hand \p M: the last point of its chain (a point of a link).
template <const auto& M>
[[nodiscard]] constexpr LinkPoint finger_tip(int f) {
  const Finger& finger = M.fingers[static_cast<std::size_t>(f)];
  return finger.points[static_cast<std::size_t>(finger.size - 1)];
}

/// \p q with the thumb of hand \p M turned to oppose the fingers: each joint that moves the thumb's
/// tip, moves no other fingertip and has no closing direction (a thumb's turn about the palm, such
/// as the Shadow hand's THJ5 and THJ3) set, on a grid of 41 values over its range and twice in
/// turn, to the value at which the thumb tip comes nearest the centroid of the other fingertips
/// when every closing joint is at its closed limit (closed_targets): the hand's own opposition. A
/// hand whose thumb opposes through its closing joints (the SDH, the Barrett, the Allegro, the
/// LEAP hand) keeps \p q.
template <const auto& M>
  requires HandModel<decltype(M)>
[[nodiscard]] Vec<M.nq> opposed_thumb(Vec<M.nq> q) {
  const Vec<M.nq> dir = closing_directions<M>(), lo = lower_limits<M>(), hi = upper_limits<M>();
  const auto tip = [](std::size_t f) { return finger_tip<M>(static_cast<int>(f)); };
  const auto moves = [](int link, int entry) {
    for (const SupportJoint& j : M.support(link))
      if (j.q == entry) return true;
    return false;
  };
  const auto thumb = static_cast<std::size_t>(M.thumb);
  std::vector<int> turns;
  for (int i = 0; i < M.nq; ++i) {
    if (dir[i] != 0.0 || !moves(tip(thumb).link, i)) continue;
    bool other = false;
    for (std::size_t f = 0; f < M.fingers.size(); ++f)
      other = other || (f != thumb && moves(tip(f).link, i));
    if (!other) turns.push_back(i);
  }
  KinematicsData<M> d;
  const auto gap = [&](const Vec<M.nq>& x) {
    forward_kinematics(d, closed_targets<M>(x));
    Vec3 centroid = Vec3::Zero();
    for (std::size_t f = 0; f < M.fingers.size(); ++f)
      if (f != thumb) centroid += world_point(d, tip(f));
    centroid /= static_cast<double>(M.fingers.size() - 1);
    return (world_point(d, tip(thumb)) - centroid).norm();
  };
  for (int round = 0; round < 2; ++round)
    for (const int i : turns) {
      double best = gap(q), value = q[i];
      for (int k = 0; k <= 40; ++k) {
        Vec<M.nq> x = q;
        x[i] = lo[i] + (hi[i] - lo[i]) * k / 40.0;
        const double g = gap(x);
        if (g < best) {
          best = g;
          value = x[i];
        }
      }
      q[i] = value;
    }
  return q;
}

/// A grasp of hand \p M: its root link's pose in the object frame and its joints.
template <const auto& M>
  requires HandModel<decltype(M)>
struct HandGrasp {
  Eigen::Isometry3d root = Eigen::Isometry3d::Identity();
  Vec<M.nq> q = Vec<M.nq>::Zero();
};

/// A planned motion (the topological methods): the configurations of the model the plan moved (on
/// the arm: the arm's joints, then the hand's; on a free base: the base's, then the hand's), one
/// per step, time_step apart, in a world where the object stands at world_object.
struct PlannedMotion {
  std::vector<std::string_view> joints;  ///< the names of the configuration's entries
  std::vector<Eigen::VectorXd> q;        ///< the plan's T + 1 configurations (rad; m, prismatic)
  double time_step = 0.0;                ///< s
  Eigen::Isometry3d world_object = Eigen::Isometry3d::Identity();  ///< the object in that world
};

/// A grasp of hand \p M transferred from another hand: where the hand ended (object frame), how it
/// was planned, the stability suite. SdhTransfer (transfer.hpp) is the SDH's.
template <const auto& M>
  requires HandModel<decltype(M)>
struct HandTransfer {
  static constexpr int curves = hand_curve_count<M>;
  TransferMethod method = TransferMethod::topological;
  /// The method produced a hand pose of its own (else nothing was simulated and reason says
  /// why); a method that could not do its work is never reported with another method's pose.
  bool planned = false;
  std::string reason;  ///< why not planned, or the planner's termination
  Eigen::Isometry3d hand_pose = Eigen::Isometry3d::Identity();  ///< the root link, object frame
  Vec<M.nq> q_open = Vec<M.nq>::Zero();                         ///< the joints before closing
  /// The hand (root link, object frame, and joints) where the method put it before moving it in
  /// to contact along its approach; unset when it was not placed.
  std::optional<HandGrasp<M>> pregrasp;
  /// The topological methods' plan (the no_plan control has none); unset for the baselines.
  std::optional<PlannedMotion> motion;
  Vec<M.nq> q_closed = Vec<M.nq>::Zero();  ///< when closing ended
  ClosingRecord closing;                   ///< what closing did (the object's motion, contacts)
  /// w of the hand's curves after closing, around the centre of mass (topological: around its
  /// winding reference).
  Vec<curves> winding = Vec<curves>::Zero();
  /// The windings the method aimed at, around the same point as `winding`, for each of the
  /// hand's curves: from the source hand's (the human's for the SDH: its two largest, the
  /// paper's descriptor); never the corrected targets of closing_corrections. Unset for the
  /// baselines, which aim at no winding.
  std::optional<Vec<curves>> source_winding;
  double plan_ms = 0.0;  ///< time of the method's own planning (ms)
  int sweeps = 0;        ///< AICO sweeps (topological only)
  /// Topological only: the windings of the hand's curves at each step of the plan and their
  /// targets (the paper's Fig. 7), and AICO's sweeps.
  std::vector<Vec<curves>> winding_plan, winding_targets;
  std::vector<AicoSweepRecord> sweep_log;
  StabilityResult stability;              ///< the deciding judge's verdict and records
  std::optional<StabilityResult> second;  ///< the other judge's, if there is one
  QualityRecord quality;                  ///< Ferrari-Canny epsilon when closing ended
  /// The arm setting (TransferOptions::arm_object): the arm's joints that put the hand at
  /// hand_pose (arm_reach()); unset without the arm setting.
  std::optional<Vec<7>> arm_joints;
  /// Where the object was when closing ended (it starts at the identity): with hand_pose and
  /// q_closed, the grasp that the stability suite started from.
  Eigen::Isometry3d object_pose = Eigen::Isometry3d::Identity();
  [[nodiscard]] bool stable() const noexcept { return planned && stability.stable; }
};

/// The human demonstration \p g as a source grasp (its palm pose and joints when closing ended).
[[nodiscard]] inline HandGrasp<models::human_hand> source_grasp(const HumanGrasp& g) {
  return {g.hand_pose, g.q};
}

/// The transferred grasp \p t as a source grasp for another transfer (its pose and joints when
/// closing ended).
template <const auto& M>
[[nodiscard]] HandGrasp<M> source_grasp(const HandTransfer<M>& t) {
  return {t.hand_pose, t.q_closed};
}

namespace detail {
// The pose (object frame) of frame `at` of hand M at g, turned as grasp_frame turns the grasp
// frame (z the approach, x up: hand_profile's axes, in the world).
template <const auto& M>
Eigen::Isometry3d turned_frame(const HandGrasp<M>& g, int at) {
  const HandProfile<M> profile = hand_profile<M>();
  KinematicsData<M> d;
  forward_kinematics(d, g.q);
  const Eigen::Matrix3d R = g.root.linear() * frame_pose(d, profile.frame).linear();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = palm_rotation(gripper_hand_axes, R * profile.axes.approach, R * profile.axes.up);
  T.translation() = g.root * frame_pose(d, at).translation();
  return T;
}

// The root pose of hand M (joints q) that puts frame `at`, turned as turned_frame turns it, at T.
template <const auto& M>
Eigen::Isometry3d root_for_turned_frame(const Eigen::Isometry3d& T, const Vec<M.nq>& q, int at) {
  const HandProfile<M> profile = hand_profile<M>();
  KinematicsData<M> d;
  forward_kinematics(d, q);
  Eigen::Isometry3d local = frame_pose(d, at);
  local.linear() =
      frame_pose(d, profile.frame).linear() *
      palm_rotation(profile.axes, gripper_hand_axes.approach, gripper_hand_axes.up).transpose();
  return T * local.inverse();
}
}  // namespace detail

/// The pose (object frame) of the frame that hand \p M grasps with (hand_profile) at \p g,
/// rotated so that its z axis is the hand's approach and its x axis its "up": the frame in which
/// two hands meet.
template <const auto& M>
[[nodiscard]] Eigen::Isometry3d grasp_frame(const HandGrasp<M>& g) {
  return detail::turned_frame(g, hand_profile<M>().frame);
}

/// The root pose of hand \p M (joints \p q) that puts its grasp frame at \p T (grasp_frame's
/// convention: z the approach, x up; object frame).
template <const auto& M>
[[nodiscard]] Eigen::Isometry3d root_for_grasp_frame(const Eigen::Isometry3d& T,
                                                     const Vec<M.nq>& q) {
  return detail::root_for_turned_frame<M>(T, q, hand_profile<M>().frame);
}

/// The pose (object frame) of hand \p M's palm centre (its model's palm frame) at \p g, turned as
/// grasp_frame turns the grasp frame (z the approach, x up): where the paper's autoclose puts one
/// hand's palm on another's. For every hand but the human hand and the SDH, the palm centre is
/// the grasp frame.
template <const auto& M>
[[nodiscard]] Eigen::Isometry3d palm_frame(const HandGrasp<M>& g) {
  return detail::turned_frame(g, detail::palm_frame_of<M>());
}

/// The root pose of hand \p M (joints \p q) that puts its palm frame at \p T (palm_frame's
/// convention).
template <const auto& M>
[[nodiscard]] Eigen::Isometry3d root_for_palm_frame(const Eigen::Isometry3d& T,
                                                    const Vec<M.nq>& q) {
  return detail::root_for_turned_frame<M>(T, q, detail::palm_frame_of<M>());
}

/// The approach of hand \p M's grasp frame (hand_profile) in the frame of its root link, at
/// joints \p q.
template <const auto& M>
[[nodiscard]] Vec3 grasp_approach(const Vec<M.nq>& q) {
  const HandProfile<M> profile = hand_profile<M>();
  KinematicsData<M> d;
  forward_kinematics(d, q);
  return d.frame_R[static_cast<std::size_t>(profile.frame)] * profile.axes.approach;
}

/// The windings of hand \p M's curves around \p p (object frame) with its root at \p root (object
/// frame) and joints \p q.
template <const auto& M>
  requires HandModel<decltype(M)>
[[nodiscard]] Vec<hand_curve_count<M>> hand_windings(const Vec3& p, const Eigen::Isometry3d& root,
                                                     const Vec<M.nq>& q) {
  KinematicsData<M> d;
  forward_kinematics(d, q);
  return WindingTask<M>(Vec3(root.inverse() * p)).value(d);
}

/// The configuration of hand \p M on its free base (FreeBase) with its root link at \p root and
/// joints \p q_hand: placed by its palm-centre frame.
template <const auto& M>
  requires HandModel<decltype(M)>
[[nodiscard]] Vec<FreeBase<M>::model.nq> free_configuration(const Eigen::Isometry3d& root,
                                                            const Vec<M.nq>& q_hand) {
  constexpr int palm = detail::palm_frame_of<M>();
  KinematicsData<M> d;
  forward_kinematics(d, q_hand);
  return place_frame<FreeBase<M>::model>(root * frame_pose(d, palm), palm, q_hand);
}

/// Why hand \p M cannot be simulated at \p root with joints \p q (non-finite joints, or a
/// non-finite or far pose, which HandScene refuses), or empty if it can.
template <const auto& M>
[[nodiscard]] std::string unusable_hand_pose(const Eigen::Isometry3d& root, const Vec<M.nq>& q) {
  if (!q.allFinite()) return "the hand's joints are not finite";
  const std::string problem = HandScene<M>::hand_pose_problem(root);
  return problem.empty() ? problem : "the hand pose cannot be simulated (" + problem + ")";
}

/// The scene of hand \p M at \p root (object frame) with joints \p q_open (clamped to its limits)
/// on \p object, the friction of M's surface (hand_surface) on the object's materials.
template <const auto& M>
[[nodiscard]] HandScene<M> hand_scene(const GraspObject& object, const Eigen::Isometry3d& root,
                                      const Vec<M.nq>& q_open, const GraspSimOptions& sim) {
  return HandScene<M>(root, clamp_to_limits<M>(q_open),
                      object_spec(object, hand_surface<M>(), sim.friction), sim.scene);
}

/// Closes hand \p M at \p root (its root link in the object frame) with joints \p q_open on the
/// object, holds, and judges the scene as closing left it (judge_grasp, with the second judge
/// \p second if set); fills the simulation fields of \p r.
template <const auto& M>
void simulate_hand_grasp(const GraspObject& object, const Eigen::Isometry3d& root,
                         const Vec<M.nq>& q_open, const GraspSimOptions& sim,
                         const SecondJudge<M>& second, HandTransfer<M>& r) {
  auto scene = hand_scene<M>(object, root, q_open, sim);
  const auto closed = close_hand(scene, sim.close);
  r.hand_pose = root;
  r.q_open = q_open;
  r.q_closed = closed.q_closed;
  r.closing = closing_record(closed);
  r.winding = hand_windings<M>(object.centre_of_mass(), root, closed.q_closed);
  r.object_pose = scene.object_pose();
  GraspJudgement judged = judge_grasp(scene, object, sim, second);
  r.stability = std::move(judged.stability);
  r.second = std::move(judged.second);
  r.quality = std::move(judged.quality);
}

/// Hand \p M's root pose \p root (object frame, joints \p q_hand) moved along \p approach so that
/// the hand is sim.contact_gap from the object: backed off first if it overlaps the object; if
/// \p advance, also moved in (at most \p advance metres) if it is clear. Nothing if it cannot be
/// placed (it stays inside the object over a stand-off of travel).
template <const auto& M>
[[nodiscard]] std::optional<Eigen::Isometry3d> place_hand_at_contact(
    const GraspObject& object, const Eigen::Isometry3d& root, const Vec<M.nq>& q_hand,
    const Vec3& approach, const GraspSimOptions& sim, double advance = 0.0) {
  constexpr auto& f = FreeBase<M>::model;
  constexpr int base = f.find_link(M.links[0].spec.name.view());
  const Composite shape = object.composite();
  KinematicsData<f> d;
  const auto root_of = [&](const Vec<f.nq>& q) {
    forward_kinematics(d, q);
    return link_pose(d, base);
  };
  const Vec<f.nq> q = free_configuration<M>(root, q_hand);
  forward_kinematics(d, q);
  const bool clear = hand_object_distance(d, shape) >= sim.contact_gap;
  if (clear && advance <= 0.0) return root_of(q);
  Vec<f.nq> start = q;
  if (!clear) start.template head<3>() -= sim.standoff * approach.normalized();
  const double travel = clear ? advance : sim.standoff;
  const auto moved = approach_until_contact<f>(start, approach, shape, sim.contact_gap, travel);
  if (moved) return root_of(*moved);
  if (clear) return root_of(q);  // nothing within reach ahead: stay
  return std::nullopt;
}

/// \p q_hand opened until hand \p M at \p root (object frame) is sim.contact_gap clear of the
/// object: each joint moved 0.05 rad a step the way hand_profile<M>() opens it, within its limits,
/// until the hand is clear or fully open; joints that do not open are kept. A hand opens around
/// an object before it closes on it; backing it off instead can take the object out of its reach.
/// \p q_hand itself if it is clear.
template <const auto& M>
[[nodiscard]] Vec<M.nq> open_hand_until_clear(const GraspObject& object,
                                              const Eigen::Isometry3d& root, Vec<M.nq> q_hand,
                                              const GraspSimOptions& sim) {
  constexpr auto& f = FreeBase<M>::model;
  const Composite shape = object.composite();
  const Vec<M.nq> lo = lower_limits<M>(), hi = upper_limits<M>();
  const Vec<M.nq> dir = hand_profile<M>().opening;
  KinematicsData<f> d;
  for (;;) {
    forward_kinematics(d, free_configuration<M>(root, q_hand));
    if (hand_object_distance(d, shape) >= sim.contact_gap) return q_hand;
    Vec<M.nq> opened = q_hand;
    for (int i = 0; i < M.nq; ++i) {
      if (dir[i] < 0.0) opened[i] = std::max(lo[i], q_hand[i] - 0.05);
      if (dir[i] > 0.0) opened[i] = std::min(hi[i], q_hand[i] + 0.05);
    }
    if (opened == q_hand) return q_hand;  // fully open
    q_hand = opened;
  }
}

}  // namespace topograsp
