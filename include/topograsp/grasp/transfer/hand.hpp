// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Any hand to any hand: transfer_hand() moves a grasp of any hand model with a hand description
/// (the human hand, the SDH, an imported Allegro, ...) to any other on a free-floating base, by any
/// method; transfer_hand_on_arm() by the topological method with the hand on the Schunk arm. The
/// source's windings around the object become the target's winding targets (winding_targets).
/// docs/transfer.md, "Any hand", states every rule; docs/results.md, "Any hand to any hand",
/// measures them.
#pragma once

#include <string>

#include <topograsp/grasp/transfer/fingertip.hpp>
#include <topograsp/grasp/transfer/topological.hpp>
#include <topograsp/grasp/transfer/transplant.hpp>
#include <topograsp/grasp/transfer/virtual_finger.hpp>

namespace topograsp {

/// The methods transfer_hand() runs: every method of the fair experiment but closed_windings
/// (its closing corrections run on the arm: transfer_hand_on_arm, transfer()) and
/// shuffled_windings (it needs another demonstration: transfer_shuffled()): the topological
/// method, its named variants (paper, paper_line, paper_approach, no_windings, nearest_point),
/// the no_plan control, and the autoclose, transplant, fingertip and virtual-finger baselines.
[[nodiscard]] constexpr bool any_hand_method(TransferMethod m) noexcept {
  return m != TransferMethod::closed_windings && m != TransferMethod::shuffled_windings;
}

namespace detail {

// The baseline method (one that is not is_topological) from source to hand Target: the one
// dispatch of transfer_hand() and transfer(). Throws naming "method" for a topological method.
template <const auto& Target>
HandTransfer<Target> baseline_grasp(TransferMethod method, const GraspObject& object,
                                    const SourceGrasp& source, const TransferOptions& options,
                                    const SecondJudge<Target>& second) {
  switch (method) {
    case TransferMethod::autoclose:
      return autoclose_grasp<Target>(object, source, options, second);
    case TransferMethod::transplant:
      return transplant_grasp<Target>(object, source, options, second);
    case TransferMethod::fingertip:
      return fingertip_grasp<Target>(object, source, options, second);
    case TransferMethod::virtual_finger:
      return virtual_finger_grasp<Target>(object, source, options, second);
    default:
      throw_invalid_argument("method", std::string(to_string(method)) + " is not a baseline");
  }
}

// The topological method (or a variant) from source, a grasp of any hand, to hand Target on
// the arm (on_arm) or its free base: the source's windings around the winding reference become
// Target's targets (winding_targets), then topological_on_arm or topological_free. A source that
// unusable_source refuses is refused.
template <const auto& Target, bool on_arm>
HandTransfer<Target> topological_from_source(TransferMethod method, const GraspObject& object,
                                             const SourceGrasp& source,
                                             const TransferOptions& options,
                                             const SecondJudge<Target>& second) {
  TransferRun<Target> run(method, unusable_source(source), options);
  if (run.refused()) return run.unplanned();
  const Eigen::Isometry3d& meet = source.grasp_frame;
  const Vec3 reference =
      winding_reference_point(object, meet.translation(), options.winding_reference);
  const Vec<hand_curve_count<Target>> y =
      winding_targets<hand_curve_count<Target>>(source_windings(source, reference));
  if constexpr (on_arm)
    return topological_on_arm<Target>(object, meet, y, reference, options, second, run);
  else
    return topological_free<Target>(object, meet, y, reference, options, second, run);
}

}  // namespace detail

/// Transfers \p source, a grasp of any hand on \p object (a SourceGrasp; a HandGrasp of any hand
/// model converts to one: describe_source), to hand \p Target on a free base, by \p method. It
/// compiles once per target hand, whatever the source:
/// - autoclose (autoclose_grasp, the paper's baseline): Target's palm frame at the source's
///   (palm_frame), its joints at base_preshape, backed off along its approach only as far as
///   needed to clear the object, closed until contact;
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
/// A source grasp that unusable_source refuses (not finite, fewer than two fingers, no curve), or
/// a hand that cannot be placed clear of the object, gives an unplanned result (planned false)
/// whose reason says why; a plan that makes no progress is judged at its start, and its reason says
/// so.
/// \throws topograsp::invalid_argument naming "method" for closed_windings (on the arm only:
/// transfer_hand_on_arm, transfer()) and shuffled_windings (transfer_shuffled()), and as
/// validate_transfer_parameters for options out of range.
template <const auto& Target>
  requires HandModel<decltype(Target)>
[[nodiscard]] HandTransfer<Target> transfer_hand(TransferMethod method, const GraspObject& object,
                                                 const SourceGrasp& source,
                                                 const TransferOptions& given = {},
                                                 const SecondJudge<Target>& second = {}) {
  if (!any_hand_method(method))
    detail::throw_invalid_argument("method",
                                   "transfer_hand runs every method but closed_windings and "
                                   "shuffled_windings; " +
                                       std::string(to_string(method)) +
                                       " runs on the arm (transfer_hand_on_arm, transfer())");
  validate_transfer_parameters(given);
  const TransferOptions options = transfer_method_options(method, given);
  if (!is_topological(method))
    return detail::baseline_grasp<Target>(method, object, source, options, second);
  return detail::topological_from_source<Target, false>(method, object, source, options, second);
}

/// Transfers \p source, a grasp of any hand on \p object (SourceGrasp), to hand \p Target on the
/// Schunk arm (OnArm<Target>: the hand's root at the flange), by the topological method or one of
/// its variants (closed_windings included): the paper's planner for any hand. The source's windings
/// around the winding reference become Target's winding targets (winding_targets); the object is
/// placed so that the source's grasp frame maps onto Target's at the arm's ready pose
/// (options.arm_ready, base_preshape) pushed out by options.backoff (in the arm setting,
/// options.arm_object, the object stays where it is and the arm reaches that start by inverse
/// kinematics); AICO plans the arm and the
/// hand with the tasks of transfer_topological; the final hand, without the arm, moves on until
/// contact (at most final_approach), closes and is judged (with \p second if set).
///
/// A source grasp that unusable_source refuses or a plan that cannot be placed gives an unplanned
/// result whose reason says why. \throws topograsp::invalid_argument naming "method" for the
/// baselines (autoclose, transplant, fingertip, virtual_finger: they place the hand without an arm,
/// transfer_hand), and as validate_transfer_parameters for options out of range.
template <const auto& Target>
  requires HandModel<decltype(Target)>
[[nodiscard]] HandTransfer<Target> transfer_hand_on_arm(TransferMethod method,
                                                        const GraspObject& object,
                                                        const SourceGrasp& source,
                                                        const TransferOptions& given = {},
                                                        const SecondJudge<Target>& second = {}) {
  if (!is_topological(method))
    detail::throw_invalid_argument("method", "transfer_hand_on_arm plans with the arm; " +
                                                 std::string(to_string(method)) +
                                                 " places the hand without it (transfer_hand)");
  validate_transfer_parameters(given);
  const TransferOptions options = transfer_method_options(method, given);
  return detail::topological_from_source<Target, true>(method, object, source, options, second);
}

}  // namespace topograsp
