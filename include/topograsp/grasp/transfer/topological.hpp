// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Topological synergies (the paper): the source's windings around the object become the target
/// hand's winding targets, and AICO plans the hand, on a free base or on the Schunk arm, toward
/// them with the collision, approach-axis, joint-limit and line tasks. One planner serves both
/// bases (detail::topological_plan); they differ only in where the plan starts.
#pragma once

#include <algorithm>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include <topograsp/aico/solver.hpp>
#include <topograsp/grasp/transfer/common.hpp>
#include <topograsp/task/axis_task.hpp>
#include <topograsp/task/collision_task.hpp>
#include <topograsp/task/joint_limit_task.hpp>
#include <topograsp/task/line_task.hpp>
#include <topograsp/task/task_set.hpp>

namespace topograsp {

/// The winding targets of a hand with \p K curves from a source hand's windings \p w (any number
/// of curves, at least one): the k-th largest of \p w for curve k, the smallest for the curves
/// beyond \p w's count. For K = 2 this is the paper's descriptor, the two largest, largest first.
/// \throws topograsp::invalid_argument naming "windings" if \p w is empty or not finite.
template <int K>
[[nodiscard]] Vec<K> winding_targets(const Eigen::VectorXd& w) {
  if (w.size() == 0 || !w.allFinite())
    detail::throw_invalid_argument("windings", "expected at least one finite winding");
  std::vector<double> sorted(w.data(), w.data() + w.size());
  std::sort(sorted.begin(), sorted.end(), std::greater<>());
  Vec<K> y;
  for (int k = 0; k < K; ++k)
    y[k] = sorted[static_cast<std::size_t>(std::min<Eigen::Index>(k, w.size() - 1))];
  return y;
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

/// The task set of the topological method for model \p A, a hand on a free base (FreeBase) or on
/// the arm (OnArm): the windings of the hand's curves around a point (interpolated from the start
/// to the targets), the collision potential against the object, the approach axis of the hand's
/// grasp frame, the joint limits, and the grasp frame on the source's approach line.
template <const auto& A>
using TopologicalTasks =
    TaskSet<WindingTask<A>, CollisionTask<A>, AxisTask<A>, JointLimitTask<A>, LineTask<A>>;

/// Builds the topological task set of hand \p M on base model \p A (OnArm<M>::model by default,
/// or FreeBase<M>::model) for an object at \p T_world_object whose source windings are \p y
/// around \p reference (object frame), with the approach of M's grasp frame (hand_profile) to be
/// along \p approach (world) on the line through \p grasp_point (world: the source's grasp
/// centre); \p d holds the kinematics of the start configuration (the winding targets start from
/// its values). \p axis_target is the approach axis task's target (world, unit: \p approach
/// normalised, as the arm's planner passes it).
template <const auto& M, const auto& A = OnArm<M>::model>
  requires HandModel<decltype(M)>
[[nodiscard]] TopologicalTasks<A> topological_tasks(
    const GraspObject& object, const Eigen::Isometry3d& T_world_object,
    const Vec<hand_curve_count<M>>& y, const Vec3& reference, const Vec3& grasp_point,
    const Vec3& approach, const KinematicsData<A>& d, const TransferOptions& options,
    const Vec3& axis_target) {
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
      scheduled(AxisTask<A>(frame, profile.axes.approach), constant_target<3>(axis_target),
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
// non-finite values, too many rejections): the caller then judges the plan's start.
template <class Problem, class Plan, class Out>
bool record_plan(const Problem& problem, const Plan& plan, Out& out) {
  out.sweeps = plan.sweeps;
  out.reason = std::string(to_string(plan.termination));
  out.sweep_log = plan.sweep_log;
  out.winding_plan.clear();
  out.winding_targets.clear();
  const auto& windings = problem.stack().template get<0>();
  typename Problem::Kinematics d_step;
  for (std::size_t t = 0; t < plan.q.size(); ++t) {
    forward_kinematics(d_step, plan.q[t]);
    out.winding_plan.push_back(windings.task.value(d_step));
    out.winding_targets.push_back(windings.target.at(static_cast<int>(t), problem.steps()));
  }
  const bool moved = std::any_of(plan.sweep_log.begin(), plan.sweep_log.end(),
                                 [](const AicoSweepRecord& s) { return s.accepted; });
  if (!moved) out.reason = "the plan made no progress (" + out.reason + "): judged at its start";
  return moved;
}

// Where a topological plan of a hand on base model A starts, in the plan's world: the start
// configuration q0, the object's pose, the source's grasp point and approach (the line task's line;
// axis_target, the approach axis task's target), and along what the planned hand moves on until
// contact: the hand's own grasp approach at its planned joints, or the source's approach (object
// frame) when along_source is set.
template <const auto& A>
struct TopologicalStart {
  Vec<A.nq> q0;
  Eigen::Isometry3d world_object = Eigen::Isometry3d::Identity();
  Vec3 grasp_point = Vec3::Zero();
  Vec3 approach = Vec3::UnitZ();
  Vec3 axis_target = Vec3::UnitZ();
  bool along_source = false;
};

// The topological method for hand M on base model A from start, toward the source windings y
// around reference (object frame), into run: AICO plans with topological_tasks; the final hand,
// without its base, moves on until contact (at most options.final_approach), closes until contact
// and is judged (with second if set). With options.closing_corrections the targets are corrected by
// the windings that closing leaves and the plan made again (the plan whose closed windings come
// nearest y is kept). A plan that makes no progress, and the no_plan control (options.plan
// false), leave the hand at the plan's start, judged as a plan's end is (every variant alike:
// never counted unstable without a simulation); r.reason says so. Not planned when the hand
// cannot be placed; r.reason keeps the planner's termination otherwise.
template <const auto& M, const auto& A>
HandTransfer<M> topological_plan(const GraspObject& object, const TopologicalStart<A>& start,
                                 const Vec<hand_curve_count<M>>& y, const Vec3& reference,
                                 const TransferOptions& options, const SecondJudge<M>& second,
                                 TransferRun<M>& run) {
  constexpr int K = hand_curve_count<M>;
  KinematicsData<A> d;
  forward_kinematics(d, start.q0);
  constexpr int root_link = A.find_link(M.links[0].spec.name.view());
  // One plan toward the winding targets `target`: fills out's plan records, and its hand_pose and
  // q_open with the placed hand; false (out.reason says why) if it cannot be placed.
  const auto plan_for = [&](const Vec<K>& target, HandTransfer<M>& out) {
    Vec<A.nq> q_end = start.q0;
    if (options.plan) {
      AicoProblem<A, TopologicalTasks<A>> problem(
          topological_tasks<M, A>(object, start.world_object, target, reference, start.grasp_point,
                                  start.approach, d, options, start.axis_target),
          start.q0, options.aico);
      AicoWorkspace ws(problem);
      const AicoResult<A.nq> plan = solve(problem, ws);
      if (record_plan(problem, plan, out)) q_end = plan.q.back();
      PlannedMotion& motion = out.motion.emplace();
      for (int i = 0; i < A.nq; ++i) motion.joints.push_back(A.joint_name(i));
      for (const Vec<A.nq>& q : plan.q) motion.q.emplace_back(q);
      motion.time_step = problem.step_length();
      motion.world_object = start.world_object;
    } else {
      out.reason = "no plan (the no_plan control): judged at its start";
    }
    KinematicsData<A> d_end;
    forward_kinematics(d_end, q_end);
    const Eigen::Isometry3d root = start.world_object.inverse() * link_pose(d_end, root_link);
    const Vec<M.nq> q_hand = clamp_to_limits<M>(Vec<M.nq>(q_end.template tail<M.nq>()));
    const Vec3 along =
        start.along_source ? start.approach : Vec3(root.linear() * grasp_approach<M>(q_hand));
    std::string why;
    out.pregrasp = HandGrasp<M>{root, q_hand};
    const auto placed =
        placed_for_closing<M>(object, root, q_hand, along, options.final_approach, options.sim,
                              "the planned hand penetrates the object", why);
    if (!placed) {
      out.reason = std::move(why);
      return false;
    }
    out.hand_pose = *placed;
    out.q_open = q_hand;
    return true;
  };
  HandTransfer<M>& r = run.r;
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
  if (!placed) return run.unplanned();
  run.stop_clock();
  const Eigen::Isometry3d hand = r.hand_pose;
  const Vec<M.nq> q_open = r.q_open;
  HandTransfer<M> out = run.judge(object, hand, q_open, options.sim, second);
  if (options.winding_reference != WindingReference::centre_of_mass)
    out.winding = hand_windings<M>(reference, hand, out.q_closed);
  return out;
}

// The topological method for hand M on the arm (OnArm<M>), the source's grasp frame source_frame
// (object frame) and windings y around reference (object frame) given: the object placed (turned)
// so that the source's grasp frame maps onto M's at the ready pose (options.arm_ready,
// base_preshape), pushed out by options.backoff, or in the arm setting (options.arm_object) left
// where it is, the plan starting where the arm reaches the same start relative to the object
// (arm_reach() from the ready pose; not planned, saying why, if it cannot); then
// topological_plan; the final hand moves on along its own approach.
template <const auto& M>
HandTransfer<M> topological_on_arm(const GraspObject& object, const Eigen::Isometry3d& source_frame,
                                   const Vec<hand_curve_count<M>>& y, const Vec3& reference,
                                   const TransferOptions& options, const SecondJudge<M>& second,
                                   TransferRun<M>& run) {
  constexpr auto& A = OnArm<M>::model;
  TopologicalStart<A> start;
  start.q0 << options.arm_ready, base_preshape<M>(options);
  KinematicsData<A> d;
  forward_kinematics(d, start.q0);
  const HandProfile<M> profile = hand_profile<M>();
  Eigen::Isometry3d gc = frame_pose(
      d, A.find_frame(M.frames[static_cast<std::size_t>(profile.frame)].spec.name.view()));
  gc.linear() =
      gc.linear() * palm_rotation(profile.axes, gripper_hand_axes.approach, gripper_hand_axes.up);
  if (options.arm_object) {
    // The arm setting: the source's grasp frame where the fixed object puts it. The arm moves
    // from its ready pose, by its inverse kinematics as every method's hand is reached, to the
    // start of the hand setting (the hand's grasp frame on the source's, options.backoff short
    // along the approach, the pre-shape), clear of the object, and the plan starts there.
    start.world_object = *options.arm_object;
    const Eigen::Isometry3d source_world = start.world_object * source_frame;
    start.approach = source_world.linear().col(2);
    start.axis_target = start.approach.normalized();
    start.grasp_point = source_world.translation();
    const Vec<M.nq> pre = base_preshape<M>(options);
    const Eigen::Isometry3d short_of =
        Eigen::Translation3d(-options.backoff * source_frame.linear().col(2)) * source_frame;
    const ArmReach reach = arm_reach(object, start.world_object,
                                     root_for_grasp_frame<M>(short_of, pre), options.arm_ready);
    run.r.source_winding = y;
    run.r.arm_joints = reach.q_arm;
    if (!reach.reached) return run.unplanned(reach.reason + " at the plan's start");
    start.q0 << reach.q_arm, pre;
    return topological_plan<M>(object, start, y, reference, options, second, run);
  }
  start.approach = gc.linear().col(2);
  start.axis_target = start.approach.normalized();
  // The object such that the source's grasp frame maps onto the hand's, pushed out by the backoff.
  const Eigen::Isometry3d source_centre =
      Eigen::Translation3d(options.backoff * start.approach) * gc;  // world
  start.world_object = source_centre * source_frame.inverse();
  start.grasp_point = source_centre.translation();
  return topological_plan<M>(object, start, y, reference, options, second, run);
}

// The topological method for hand M on its free base (FreeBase<M>), the source's grasp frame
// meet (object frame) and windings y around reference (object frame) given: the plan starts at the
// transplant pose (M's grasp frame at meet, joints opened as the transplant opens them), backed off
// along the approach until clear of the object and then options.backoff further; then
// topological_plan, the final hand moving on along the source's approach. Not planned when the
// start cannot be placed clear of the object.
template <const auto& M>
HandTransfer<M> topological_free(const GraspObject& object, const Eigen::Isometry3d& meet,
                                 const Vec<hand_curve_count<M>>& y, const Vec3& reference,
                                 const TransferOptions& options, const SecondJudge<M>& second,
                                 TransferRun<M>& run) {
  constexpr auto& F = FreeBase<M>::model;
  TopologicalStart<F> start;
  start.approach = start.axis_target = meet.linear().col(2);
  start.grasp_point = meet.translation();
  start.along_source = true;
  const Vec<M.nq> pre = opened_preshape<M>(options.transplant_opening, base_preshape<M>(options));
  const auto clear = place_hand_at_contact<M>(object, root_for_grasp_frame<M>(meet, pre), pre,
                                              start.approach, options.sim);
  run.r.source_winding = y;
  if (!clear) return run.unplanned("the start cannot be placed clear of the object");
  Eigen::Isometry3d start_root = *clear;
  start_root.pretranslate(-options.backoff * start.approach);
  start.q0 = free_configuration<M>(start_root, pre);
  return topological_plan<M>(object, start, y, reference, options, second, run);
}

}  // namespace detail

}  // namespace topograsp
