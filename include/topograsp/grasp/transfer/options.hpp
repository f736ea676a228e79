// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The parameters of the transfer methods (TransferOptions), the numeric ones by name with their
/// ranges (transfer_parameters: grasp_transfer --set, results.json's "transfer"), and the options
/// each topological variant runs with (transfer_method_options).
#pragma once

#include <array>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>

#include <topograsp/aico/options.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/core/parameters.hpp>
#include <topograsp/grasp/human_grasps.hpp>
#include <topograsp/grasp/transfer_method.hpp>

namespace topograsp {

/// The parameters of the transfer methods; every field has a default used by grasp_transfer.
struct TransferOptions {
  GraspSimOptions sim{};  ///< closing and stability suite of the transferred grasp
  /// The SDH's joints before closing: knuckle 0 (fingers facing the thumb), phalanges open.
  Vec<7> sdh_preshape = (Vec<7>() << 0.0, -0.3, 0.3, -0.3, 0.3, -0.3, 0.3).finished();
  /// The arm's start configuration (rad): elbow bent, the hand pointing forward.
  Vec<7> arm_ready = (Vec<7>() << 0.0, 0.5, 0.0, 1.0, 0.0, 0.5, 0.0).finished();
  /// The object is placed so that the human grasp centre lies this far beyond the SDH's grasp
  /// centre at the start, along the approach (m): the plan has to move in. In the arm setting
  /// (arm_object) the arm reaches the same start relative to the object.
  double backoff = 0.03;
  /// The arm setting (the paper's; docs/transfer.md, "The arm setting"): the object fixed at this
  /// pose in the arm's world (arm_setting_object_pose()) instead of turned to meet the hand. The
  /// topological plan on the arm then starts where the arm, moved from its ready pose (arm_ready)
  /// by arm_reach(), puts the hand at the hand setting's start (backoff short, the pre-shape), with
  /// the object where it is, and every method's hand, when it is placed for closing, must be
  /// reached by the arm without the arm entering the object (arm_reach(): inverse kinematics
  /// from the ready pose); a hand the arm cannot reach is not planned, and reason says why.
  /// Unset (the default): the object is turned to meet the topological plan's start, and the
  /// hand alone is placed and judged.
  std::optional<Eigen::Isometry3d> arm_object;
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
  /// Whether the topological method plans. False (the no_plan control): no AICO solve, the hand
  /// is judged at the plan's start, moved on until contact and closed as a plan's end is.
  bool plan = true;
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
  /// knuckle as in sdh_preshape (transplant_preshape). How the default was chosen: docs/results.md.
  double transplant_opening = 0.7;
};

/// One numeric parameter of TransferOptions (core/parameters.hpp).
using TransferParameter = Parameter<TransferOptions>;

/// The numeric parameters of TransferOptions (grasp_transfer --set NAME=VALUE; the "transfer"
/// object of results.json), each with the range set_transfer_parameter accepts. Lengths are in
/// m, precisions are task weights (per m^2 for the line task); 0 switches a task's term off.
inline constexpr ParameterTable<TransferOptions, 15> transfer_parameters{{
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
  return find_parameter(transfer_parameters, name);
}

/// Sets the parameter called \p name (one of transfer_parameters) of \p options to \p value.
/// \throws topograsp::invalid_argument naming "name" (unknown; the message lists the names) or
/// the parameter (\p value outside its range, or not finite; the message gives the range);
/// \p options is unchanged then.
inline void set_transfer_parameter(TransferOptions& options, std::string_view name, double value) {
  set_parameter(options, transfer_parameters, name, value, "transfer parameter");
}

/// Checks every parameter of transfer_parameters in \p options against its range.
/// \throws topograsp::invalid_argument naming the first parameter out of range.
inline void validate_transfer_parameters(const TransferOptions& options) {
  validate_parameters(options, transfer_parameters);
}

/// \p options as the topological variant \p method runs with (see TransferMethod): the paper's
/// method switches the line task and the final approach off (line_precision_mid/_end and
/// final_approach 0), paper_line only the final approach, paper_approach only the line task;
/// no_windings sets both winding precisions to 0; nearest_point the nearest-point winding
/// reference; closed_windings two closing corrections; no_plan no plan (plan false).
/// topological, shuffled_windings (whose difference is the grasp it is given) and the other
/// methods take \p options as given.
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
  if (method == TransferMethod::no_plan) options.plan = false;
  return options;
}

}  // namespace topograsp
