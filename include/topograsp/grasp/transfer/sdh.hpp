// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The paper's Table I on the Schunk SDH: a human demonstration (HumanGrasp) transferred to the SDH
/// by each method, the topological one on the arm. Each is a thin call of the method for any pair
/// of hands (autoclose_grasp, transplant_grasp, fingertip_grasp, virtual_finger_grasp,
/// detail::topological_on_arm), judged also by options.sim.second_judge_sdh.
///
/// The SDH's functions are templates with nothing to give (`template <class = void>`): a
/// translation unit that includes this header for another hand does not instantiate the SDH's
/// planner and stepper (docs/architecture.md, "Compile time").
#pragma once

#include <array>
#include <string>
#include <utility>
#include <vector>

#include <topograsp/grasp/transfer/fingertip.hpp>
#include <topograsp/grasp/transfer/hand.hpp>
#include <topograsp/grasp/transfer/topological.hpp>
#include <topograsp/grasp/transfer/transplant.hpp>
#include <topograsp/grasp/transfer/virtual_finger.hpp>

namespace topograsp {

/// A grasp transferred to the SDH (HandTransfer of the SDH: its 7 joints, its two curves).
using SdhTransfer = HandTransfer<models::schunk_sdh>;

namespace detail {

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

// The SDH baseline \p run on the human grasp g, judged also by options.sim.second_judge_sdh; a
// non-finite human grasp (its descriptor too) is not planned, reason says why.
template <class Run>
SdhTransfer sdh_from_human(TransferMethod method, const HumanGrasp& g,
                           const TransferOptions& options, Run run) {
  TransferRun<models::schunk_sdh> refusal(method, unusable_human_grasp(g), options);
  if (refusal.refused()) return refusal.unplanned();
  return run(source_grasp(g), options.sim.second_judge_sdh);
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

/// The paper's baseline on the SDH (autoclose_grasp from the human hand: the SDH's palm at the
/// human's, its usual pre-shape options.sdh_preshape, closed), judged also by
/// options.sim.second_judge_sdh.
template <class = void>
[[nodiscard]] SdhTransfer transfer_autoclose(const GraspObject& object, const HumanGrasp& g,
                                             const TransferOptions& options = {}) {
  return detail::sdh_from_human(TransferMethod::autoclose, g, options, [&](auto s, auto& second) {
    return autoclose_grasp<models::schunk_sdh>(object, s, options, second);
  });
}

/// The fair transplant baseline on the SDH (transplant_grasp from the human hand: the grasp
/// centres paired, the SDH opened by options.transplant_opening), judged also by
/// options.sim.second_judge_sdh.
template <class = void>
[[nodiscard]] SdhTransfer transfer_transplant(const GraspObject& object, const HumanGrasp& g,
                                              const TransferOptions& options = {}) {
  return detail::sdh_from_human(TransferMethod::transplant, g, options, [&](auto s, auto& second) {
    return transplant_grasp<models::schunk_sdh>(object, s, options, second);
  });
}

/// The fingertip mapping of Table I: the human grasp \p g to the SDH (fingertip_grasp: the human's
/// thumb, index and ring tips onto the SDH's thumb, finger 1 and finger 2 tips), judged also by
/// options.sim.second_judge_sdh.
template <class = void>
[[nodiscard]] SdhTransfer transfer_fingertip(const GraspObject& object, const HumanGrasp& g,
                                             const TransferOptions& options = {}) {
  return detail::sdh_from_human(TransferMethod::fingertip, g, options, [&](auto s, auto& second) {
    return fingertip_grasp<models::schunk_sdh>(object, s, options, second);
  });
}

/// The fingertip targets of transfer_fingertip (fingertip_targets), the SDH's thumb tip's first.
/// \throws topograsp::invalid_argument naming "source" for a human grasp whose pose or joints are
/// not finite.
template <class = void>
[[nodiscard]] std::array<Vec3, 3> fingertip_targets(const GraspObject& object, const HumanGrasp& g,
                                                    const TransferOptions& options = {}) {
  const std::vector<Vec3> t =
      fingertip_targets<models::schunk_sdh>(object, source_grasp(g), options);
  return {t[0], t[1], t[2]};
}

/// The virtual-finger mapping of Table I: the human grasp \p g to the SDH (virtual_finger_grasp:
/// the SDH's thumb opposes the midpoint of its two finger tips), judged also by
/// options.sim.second_judge_sdh.
template <class = void>
[[nodiscard]] SdhTransfer transfer_virtual_finger(const GraspObject& object, const HumanGrasp& g,
                                                  const TransferOptions& options = {}) {
  return detail::sdh_from_human(
      TransferMethod::virtual_finger, g, options, [&](auto s, auto& second) {
        return virtual_finger_grasp<models::schunk_sdh>(object, s, options, second);
      });
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

/// Topological synergies (the paper): the human's descriptor y (its two largest windings around
/// the object's centre of mass) becomes the winding target of the SDH's two curves; AICO plans the
/// 14-DOF arm + SDH from its ready pose with the collision task, the approach direction and (our
/// addition, docs/transfer.md) the grasp centre on the human's approach line; the object is placed
/// (turned) so that the human's approach is the SDH's at the ready pose, a little out of reach.
/// The final hand, without the arm, moves on along its approach until contact, is closed until
/// contact and shaken (detail::topological_on_arm, which any hand on the arm shares:
/// transfer_hand_on_arm; the free base's planner is the same, detail::topological_plan).
template <class = void>
[[nodiscard]] SdhTransfer transfer_topological(const GraspObject& object, const HumanGrasp& g,
                                               const TransferOptions& options = {}) {
  detail::TransferRun<models::schunk_sdh> run(TransferMethod::topological,
                                              detail::unusable_human_grasp(g), options);
  if (run.refused()) return run.unplanned();
  const Vec3 reference = winding_reference_point(object, g, options.winding_reference);
  const Vec2 y = options.winding_reference == WindingReference::centre_of_mass
                     ? g.descriptor.values
                     : human_descriptor(g, reference).values;
  return detail::topological_on_arm<models::schunk_sdh>(object, detail::sdh_grasp_target(g), y,
                                                        reference, options,
                                                        options.sim.second_judge_sdh, run);
}

/// Runs \p method on the human grasp \p g (a topological variant with
/// transfer_method_options); the result's method is \p method.
template <class = void>
[[nodiscard]] SdhTransfer transfer(TransferMethod method, const GraspObject& object,
                                   const HumanGrasp& g, const TransferOptions& options) {
  if (!is_topological(method))
    return detail::sdh_from_human(method, g, options, [&](auto s, auto& second) {
      return detail::baseline_grasp<models::schunk_sdh>(method, object, s, options, second);
    });
  SdhTransfer r = transfer_topological(object, g, transfer_method_options(method, options));
  r.method = method;
  return r;
}

/// The shuffled-windings control on the SDH: topograsp's method on the human grasp \p g (its
/// grasp frame, approach and start) aimed at \p other's windings (its descriptor around the
/// object's centre of mass) instead of g's, so that what the windings add is measured apart from
/// the rest of the plan. Not planned (reason says why) when \p other is null or did not reach the
/// object; grasp_transfer's rule for choosing it: docs/transfer.md, "Controls".
template <class = void>
[[nodiscard]] SdhTransfer transfer_shuffled(const GraspObject& object, const HumanGrasp& g,
                                            const HumanGrasp* other,
                                            const TransferOptions& options) {
  if (other == nullptr || !other->reached) {
    detail::TransferRun<models::schunk_sdh> run(
        TransferMethod::shuffled_windings,
        "no other demonstration reached the object to take windings from", options);
    return run.unplanned();
  }
  HumanGrasp aimed = g;
  aimed.descriptor = other->descriptor;
  aimed.windings = other->windings;
  return transfer(TransferMethod::shuffled_windings, object, aimed, options);
}

}  // namespace topograsp
