// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Any hand to any hand: transfer_hand() moves a grasp of any hand model with a hand description
/// (the human hand, the SDH, an imported Allegro, ...) to any other, on a free-floating base, by
/// the topological method (and its named variants) or the transplant baseline. The source's
/// windings around the object become the target's winding targets (winding_targets: the paper's
/// descriptor, the two largest, for a two-curve hand such as the SDH; the k largest for a hand of
/// k curves). docs/transfer.md, "Any hand", states every rule; docs/results.md holds the
/// transfer matrix that measures them.
#pragma once

#include <algorithm>
#include <functional>
#include <string>
#include <vector>

#include <topograsp/grasp/transfer.hpp>

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

/// The methods transfer_hand() runs: every method of the fair experiment but closed_windings
/// (which needs the SDH on the arm): the topological method, its named variants (paper,
/// paper_line, paper_approach, no_windings, nearest_point), and the transplant, fingertip and
/// virtual-finger baselines.
[[nodiscard]] constexpr bool any_hand_method(TransferMethod m) noexcept {
  return m != TransferMethod::closed_windings;
}

namespace detail {

// The task set of the topological method on hand T's free base.
template <const auto& F>
using FreeTopologicalTasks =
    TaskSet<WindingTask<F>, CollisionTask<F>, AxisTask<F>, JointLimitTask<F>, LineTask<F>>;

}  // namespace detail

/// Transfers \p source, a grasp of hand \p Source on \p object, to hand \p Target on a free
/// base, by \p method:
/// - transplant (transplant_grasp): Target's grasp frame at the source's (grasp_frame: the same
///   point, approach and up), its joints at opened_preshape(options.transplant_opening,
///   base_preshape), backed off along its approach only as far as needed to clear the object,
///   closed until contact;
/// - fingertip (fingertip_grasp): Target's fingertips fitted to the source's, scaled and put on the
///   object's surface (fingertip_correspondence says which tip goes where);
/// - virtual_finger (virtual_finger_grasp): Target's thumb opposes the centroid of its other
///   fingertips along and across the source's palm or pad opposition;
/// - topological and its variants (transfer_method_options): the source's windings around the
///   winding reference (the centre of mass, or the object's point nearest the source's grasp
///   frame) become Target's winding targets (winding_targets); AICO plans Target on its free base
///   from the transplant pose, backed off until clear and then options.backoff further, with the
///   winding, collision, approach-axis, joint-limit and line tasks of transfer_topological (the
///   line through the source's grasp frame along its approach); the final hand moves on along its
///   approach until contact (at most final_approach), closes until contact and is judged.
/// Every result is judged by the stability suite in the built-in stepper and by \p second if set.
///
/// A source grasp that is not finite, a plan that makes no progress, or a hand that cannot be
/// placed clear of the object gives an unplanned result (planned false) whose reason says why.
/// \throws topograsp::invalid_argument naming "method" for closed_windings (the SDH on the arm
/// only: transfer()), and as validate_transfer_parameters for options out of range.
template <const auto& Target, const auto& Source>
  requires HandModel<decltype(Target)> && HandModel<decltype(Source)>
[[nodiscard]] HandTransfer<Target> transfer_hand(TransferMethod method, const GraspObject& object,
                                                 const HandGrasp<Source>& source,
                                                 const TransferOptions& given = {},
                                                 const SecondJudge<Target>& second = {}) {
  if (!any_hand_method(method))
    detail::throw_invalid_argument(
        "method", "transfer_hand runs every method but closed_windings; " +
                      std::string(to_string(method)) + " needs the SDH on the arm (transfer())");
  validate_transfer_parameters(given);
  const TransferOptions options = transfer_method_options(method, given);
  if (method == TransferMethod::transplant)
    return transplant_grasp<Target>(object, source, options, second);
  if (method == TransferMethod::fingertip)
    return fingertip_grasp<Target>(object, source, options, second);
  if (method == TransferMethod::virtual_finger)
    return virtual_finger_grasp<Target>(object, source, options, second);
  constexpr int K = hand_curve_count<Target>;
  constexpr auto& F = FreeBase<Target>::model;
  const auto t0 = detail::Clock::now();
  HandTransfer<Target> r;
  r.method = method;
  r.reason = detail::unusable_source_grasp(source);
  if (!r.reason.empty()) return r;
  const Eigen::Isometry3d meet = grasp_frame(source);
  const Vec3 approach = meet.linear().col(2);
  const Vec<Target.nq> pre =
      opened_preshape<Target>(options.transplant_opening, base_preshape<Target>(options));
  // The topological method: the source's windings, the start clear of the object.
  const Vec3 reference =
      winding_reference_point(object, meet.translation(), options.winding_reference);
  const Vec<hand_curve_count<Source>> source_w =
      hand_windings<Source>(reference, source.root, source.q);
  const Vec<K> y = winding_targets<K>(source_w);
  r.source_winding = y;
  const auto clear = place_hand_at_contact<Target>(object, root_for_grasp_frame<Target>(meet, pre),
                                                   pre, approach, options.sim);
  if (!clear) {
    r.plan_ms = detail::ms_since(t0);
    r.reason = "the start cannot be placed clear of the object";
    return r;
  }
  Eigen::Isometry3d start_root = *clear;
  start_root.pretranslate(-options.backoff * approach);
  const Vec<F.nq> q0 = free_configuration<Target>(start_root, pre);
  KinematicsData<F> d;
  forward_kinematics(d, q0);
  const int frame = hand_profile<Target>().frame;
  // The grasp frame's approach axis in its own coordinates (grasp_frame: z).
  const Vec3 local_approach = hand_profile<Target>().axes.approach;
  WindingTask<F> winding(reference);
  const Vec<K> w0 = winding.value(d);
  using Tasks = detail::FreeTopologicalTasks<F>;
  Tasks tasks = make_task_set(
      scheduled(std::move(winding), interpolated_target<K>(w0, y),
                precision(options.winding_precision_mid, options.winding_precision_end)),
      scheduled(CollisionTask<F>(object.composite(), options.collision_margin),
                constant_target<1>(Vec<1>::Zero()),
                constant_precision(options.collision_precision)),
      scheduled(AxisTask<F>(frame, local_approach), constant_target<3>(approach),
                precision(options.approach_precision_mid, options.approach_precision_end)),
      scheduled(JointLimitTask<F>(), constant_target<F.nq>(Vec<F.nq>::Zero()),
                constant_precision(options.limit_precision)),
      scheduled(LineTask<F>(frame, meet.translation(), approach), constant_target<2>(Vec2::Zero()),
                precision(options.line_precision_mid, options.line_precision_end)));
  AicoProblem<F, Tasks> problem(std::move(tasks), q0, options.aico);
  AicoWorkspace ws(problem);
  const AicoResult<F.nq> plan = solve(problem, ws);
  if (!detail::record_plan(problem, plan, r)) {
    r.plan_ms = detail::ms_since(t0);
    return r;
  }
  KinematicsData<F> dt;
  forward_kinematics(dt, plan.q.back());
  const Eigen::Isometry3d root = link_pose(dt, F.find_link(Target.links[0].spec.name.view()));
  const Vec<Target.nq> q_hand =
      clamp_to_limits<Target>(Vec<Target.nq>(plan.q.back().template tail<Target.nq>()));
  const auto placed = place_hand_at_contact<Target>(object, root, q_hand, approach, options.sim,
                                                    options.final_approach);
  r.plan_ms = detail::ms_since(t0);
  if (!placed) {
    r.reason = "the planned hand penetrates the object";
    return r;
  }
  if (std::string unusable = unusable_hand_pose<Target>(*placed, q_hand); !unusable.empty()) {
    r.reason = std::move(unusable);
    return r;
  }
  r.planned = true;  // r.reason keeps the planner's termination
  simulate_hand_grasp<Target>(object, *placed, q_hand, options.sim, second, r);
  if (options.winding_reference != WindingReference::centre_of_mass)
    r.winding = hand_windings<Target>(reference, r.hand_pose, r.q_closed);
  return r;
}

/// Transfers \p source, a grasp of hand \p Source on \p object, to hand \p Target on the Schunk
/// arm (OnArm<Target>: the hand's root at the flange), by the topological method or one of its
/// variants (closed_windings included): the paper's planner for any hand. The source's windings
/// around the winding reference become Target's winding targets (winding_targets); the object is
/// placed so that the source's grasp frame maps onto Target's at the arm's ready pose
/// (options.arm_ready, base_preshape) pushed out by options.backoff; AICO plans the arm and the
/// hand with the tasks of transfer_topological; the final hand, without the arm, moves on until
/// contact (at most final_approach), closes and is judged (with \p second if set).
///
/// A source grasp that is not finite or a plan that cannot be placed gives an unplanned result
/// whose reason says why. \throws topograsp::invalid_argument naming "method" for the baselines
/// (transplant, fingertip, virtual_finger: they place the hand without an arm, transfer_hand),
/// and as validate_transfer_parameters for options out of range.
template <const auto& Target, const auto& Source>
  requires HandModel<decltype(Target)> && HandModel<decltype(Source)>
[[nodiscard]] HandTransfer<Target> transfer_hand_on_arm(TransferMethod method,
                                                        const GraspObject& object,
                                                        const HandGrasp<Source>& source,
                                                        const TransferOptions& given = {},
                                                        const SecondJudge<Target>& second = {}) {
  if (!is_topological(method))
    detail::throw_invalid_argument("method", "transfer_hand_on_arm plans with the arm; " +
                                                 std::string(to_string(method)) +
                                                 " places the hand without it (transfer_hand)");
  validate_transfer_parameters(given);
  const TransferOptions options = transfer_method_options(method, given);
  const auto t0 = detail::Clock::now();
  if (std::string problem = detail::unusable_source_grasp(source); !problem.empty()) {
    HandTransfer<Target> r;
    r.method = method;
    r.reason = std::move(problem);
    return r;
  }
  const Eigen::Isometry3d meet = grasp_frame(source);
  const Vec3 reference =
      winding_reference_point(object, meet.translation(), options.winding_reference);
  const Vec<hand_curve_count<Target>> y = winding_targets<hand_curve_count<Target>>(
      hand_windings<Source>(reference, source.root, source.q));
  HandTransfer<Target> r =
      detail::topological_on_arm<Target>(object, meet, y, reference, options, second, t0);
  r.method = method;
  return r;
}

}  // namespace topograsp
