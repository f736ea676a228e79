// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// What every transfer method shares: the joints a hand starts from (base_preshape), the checks of
/// a source grasp, and detail::TransferRun: a transfer under way, its plan clock and its last steps
/// (the hand placed at contact, checked, closed and judged). docs/architecture.md, "Adding a
/// transfer method".
#pragma once

#include <chrono>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <utility>

#include <topograsp/geometry/signed_distance.hpp>
#include <topograsp/grasp/arm_reach.hpp>
#include <topograsp/grasp/hand_grasp.hpp>
#include <topograsp/grasp/human_grasps.hpp>
#include <topograsp/grasp/transfer/options.hpp>
#include <topograsp/grasp/transfer/source.hpp>

namespace topograsp {

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

namespace detail {

using Clock = std::chrono::steady_clock;
inline double ms_since(Clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
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

/// Why the human grasp \p g cannot be transferred by any method (a non-finite hand pose,
/// configuration or descriptor), or empty if it can.
[[nodiscard]] inline std::string unusable_human_grasp(const HumanGrasp& g) {
  if (!g.hand_pose.matrix().allFinite()) return "the human hand pose is not finite";
  if (!g.q.allFinite()) return "the human configuration is not finite";
  if (!g.descriptor.values.allFinite()) return "the human windings are not finite";
  return {};
}

// Hand M at root (object frame, joints q) moved along approach until it is sim.contact_gap from
// the object, at most advance further when it is clear, backed off when it overlaps
// (place_hand_at_contact), and checked for HandScene (unusable_hand_pose): the placed root, or
// nothing and why says why (unplaced when it cannot be placed clear of the object).
template <const auto& M>
std::optional<Eigen::Isometry3d> placed_for_closing(const GraspObject& object,
                                                    const Eigen::Isometry3d& root,
                                                    const Vec<M.nq>& q, const Vec3& approach,
                                                    double advance, const GraspSimOptions& sim,
                                                    std::string_view unplaced, std::string& why) {
  const auto placed = place_hand_at_contact<M>(object, root, q, approach, sim, advance);
  if (!placed) {
    why = unplaced;
    return std::nullopt;
  }
  why = unusable_hand_pose<M>(*placed, q);
  if (!why.empty()) return std::nullopt;
  return placed;
}

// A transfer to hand M under way: its result r (method set) and its plan clock, started when the
// run is made. Every method starts with one, returns unplanned() when it cannot do its work, and
// ends in judge() or place_and_judge(): r.plan_ms is the time from the start to the placed hand
// (or to the refusal), the closing and the judging not included.
template <const auto& M>
struct TransferRun {
  Clock::time_point t0 = Clock::now();
  HandTransfer<M> r;
  // The arm setting (options.arm_object): the object's pose in the arm's world and the arm's
  // ready pose, from which judge() reaches the hand.
  std::optional<Eigen::Isometry3d> arm_object;
  Vec<7> arm_ready = Vec<7>::Zero();

  // A transfer by method of a source that is unusable for the reason unusable (empty: usable),
  // with options' arm setting.
  TransferRun(TransferMethod method, std::string unusable, const TransferOptions& options)
      : arm_object(options.arm_object), arm_ready(options.arm_ready) {
    r.method = method;
    r.reason = std::move(unusable);
  }
  // Whether the source was refused at the start (only meaningful before the method sets a reason).
  [[nodiscard]] bool refused() const noexcept { return !r.reason.empty(); }
  // Stops the plan clock.
  void stop_clock() { r.plan_ms = ms_since(t0); }
  // The result, not planned (nothing simulated): the clock stopped, reason why (or r.reason kept).
  HandTransfer<M> unplanned() {
    stop_clock();
    return std::move(r);
  }
  HandTransfer<M> unplanned(std::string why) {
    r.reason = std::move(why);
    return unplanned();
  }
  // The hand at the placed root (object frame) with joints q closed until contact and judged by
  // the stability suite (and by second if set): planned; r.reason is kept. In the arm setting
  // the arm must reach it first (arm_reach), else it is unplanned with the reason why.
  HandTransfer<M> judge(const GraspObject& object, const Eigen::Isometry3d& root,
                        const Vec<M.nq>& q, const GraspSimOptions& sim,
                        const SecondJudge<M>& second) {
    if (arm_object) {
      r.hand_pose = root;
      r.q_open = q;
      const ArmReach reach = arm_reach(object, *arm_object, root, arm_ready);
      r.arm_joints = reach.q_arm;
      if (!reach.reached) return unplanned(reach.reason);
    }
    r.planned = true;
    simulate_hand_grasp<M>(object, root, q, sim, second, r);
    return std::move(r);
  }
  // placed_for_closing (root and q the pre-grasp), the clock stopped, then judge(); unplanned with
  // its reason if it cannot be placed.
  HandTransfer<M> place_and_judge(const GraspObject& object, const Eigen::Isometry3d& root,
                                  const Vec<M.nq>& q, const Vec3& approach, double advance,
                                  const GraspSimOptions& sim, const SecondJudge<M>& second,
                                  std::string_view unplaced) {
    r.pregrasp = HandGrasp<M>{root, q};
    std::string why;
    const auto placed =
        placed_for_closing<M>(object, root, q, approach, advance, sim, unplaced, why);
    if (!placed) return unplanned(std::move(why));
    stop_clock();
    return judge(object, *placed, q, sim, second);
  }
  // The baselines' last steps: q opened until the hand at root is clear of the object
  // (open_hand_until_clear), then place_and_judge along the hand's approach, at most
  // options.final_approach further.
  HandTransfer<M> open_place_and_judge(const GraspObject& object, const Eigen::Isometry3d& root,
                                       const Vec<M.nq>& q, const TransferOptions& options,
                                       const SecondJudge<M>& second) {
    const Vec<M.nq> opened = open_hand_until_clear<M>(object, root, q, options.sim);
    return place_and_judge(object, root, opened, root.linear() * grasp_approach<M>(opened),
                           options.final_approach, options.sim, second,
                           "the hand cannot be placed clear of the object");
  }
};

}  // namespace detail

}  // namespace topograsp
