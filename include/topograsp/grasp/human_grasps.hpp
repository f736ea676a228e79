// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Human demonstration grasps (paper IV, "Test data generation"): for each box hypothesis of an
/// object, the 20-DOF human hand approaches until contact, closes with its motors, and the
/// stability suite (the paper's shake and the six gravity directions, from the closing-end state)
/// decides whether the grasp is stable and so kept as a demonstration.
///
/// The functions that run the human hand's simulation are templates with nothing to give
/// (`template <class = void>`): a translation unit that includes this header but does not call
/// them does not instantiate the hand's stepper (docs/architecture.md, "Compile time").
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <string_view>

#include <topograsp/evaluation/close_hand.hpp>
#include <topograsp/evaluation/grasp_wrench.hpp>
#include <topograsp/evaluation/stability_suite.hpp>
#include <topograsp/grasp/hand_axes.hpp>
#include <topograsp/grasp/hypothesis.hpp>
#include <topograsp/grasp/placement.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/task/winding_descriptor.hpp>
#include <topograsp/task/winding_task.hpp>
#ifdef TOPOGRASP_HAVE_QHULL
#include <topograsp/evaluation/grasp_quality.hpp>
#endif

namespace topograsp {

/// A judge of a closed grasp other than the built-in stepper: given the scene as closing left it
/// and the stability options, the suite's verdict in that engine (grasp_transfer --judge sets
/// MuJoCo's, MujocoScene in mujoco/mujoco_scene.hpp).
template <const auto& M>
using SecondJudge = std::function<StabilityResult(const HandScene<M>&, const StabilityOptions&)>;

/// The Ferrari-Canny epsilon of a grasp when closing ended (computed where qhull is linked,
/// TOPOGRASP_HAVE_QHULL; evaluation/grasp_quality.hpp).
struct QualityRecord {
  bool computed = false;      ///< false in a build without qhull
  double epsilon = 0.0;       ///< > 0: force closure
  std::string status;         ///< force_closure, not_force_closure or degenerate
  std::string reason;         ///< why degenerate ("" otherwise)
  double torque_scale = 0.0;  ///< the object's max radius from its centre of mass (m)
};

/// The parameters of the grasp simulations shared by the demonstrations and the transfers.
struct GraspSimOptions {
  /// The hand scene (HandSceneOptions defaults: 8000 N/m pads, 4 solver iterations; the friction
  /// is the object's own).
  HandSceneOptions scene{};
  /// The robot hands' closing: by the motors, holding at half their torque limits (the SDH's and
  /// the Barrett's efforts are their motors' limits; CloseOptions defaults).
  CloseOptions close{};
  /// The human hand holds with this fraction of its joints' efforts. Default 1: the human
  /// model's efforts are already the torques of a comfortable holding grasp, about a fifth of
  /// maximal strength (docs/models.md), not maximal ones.
  double human_hold_fraction = 1.0;
  /// How much harder than its holding torques the human hand grips where the object's load asks
  /// for it, under the balanced hold (CloseOptions::max_grip: grip-load coupling). Default 5:
  /// the holding torques are about a fifth of a person's maximal strength (docs/models.md); 1
  /// holds with the holding torques alone.
  double human_max_grip = 5.0;
  StabilityOptions stability{};  ///< the stability suite (its seed is set per grasp)
  /// Friction between the hands and the objects: 0 (the default) takes each pair from the table
  /// of materials (friction_coefficient(), docs/objects.md); a positive value is the Coulomb
  /// coefficient of every pair, for a friction sensitivity run (grasp_transfer --friction MU).
  double friction = 0.0;
  /// A second judge of every human grasp and of every SDH transfer (empty: none), run with the
  /// same stability options on the scene as closing left it.
  SecondJudge<models::human_hand> second_judge_human;
  SecondJudge<models::schunk_sdh> second_judge_sdh;
  /// The second judge's name in results.json. Default "mujoco".
  std::string second_judge_name = "mujoco";
  /// If true, the second judge's verdict decides which grasps are stable (--judge mujoco) and
  /// the built-in's is recorded as the second. Default false.
  bool second_judge_decides = false;
  double contact_gap = 0.002;  ///< how close the approach brings the hand to the object (m)
  double standoff = 0.12;      ///< where the approach starts, back from the face (m)
  /// How the human hand approaches a hypothesis: true, palm first (approach_palm_first(): the
  /// palm moves in until it touches the object, the fingers opening where they would enter it and
  /// the hand sliding sideways where they cannot, as a person grasping an object brings the palm
  /// to it; the fingers stop contact_gap short); false (the default, the protocol of the
  /// published results), until any link first touches (approach_until_contact(), usually the
  /// opposed thumb).
  bool palm_first = false;
};

/// The open pre-shape of the human hand the demonstrations start from, a power-grasp pre-shape:
/// fingers slightly bent, the thumb opposed (CMC2 at its palmar-abduction limit, -50 degrees), so
/// that it stands about 8 cm out of the palm and its MCP and IP flexion curl it toward the finger
/// pads: the object enters the "C" of thumb and fingers, and closing wraps both around it. (With
/// the thumb in the palm plane its flexion axis is within 8 degrees of the palm normal: it sweeps
/// across the palm and never opposes the fingers.)
[[nodiscard]] inline Vec<20> human_preshape() {
  Vec<20> q = Vec<20>::Zero();
  constexpr auto& h = models::human_hand;
  for (const char* j : {"index_mcp", "middle_mcp", "ring_mcp", "pinky_mcp", "index_pip",
                        "middle_pip", "ring_pip", "pinky_pip"})
    q[h.find_joint(j)] = 0.1;
  q[h.joint("thumb_cmc1")] = 0.3;
  q[h.joint("thumb_cmc2")] = -deg(50.0);  // full palmar abduction (the joint's lower limit)
  return q;
}

/// How far a human hand fitted to a recording's 21 keypoints is from them (fit_human_hand()).
struct FitError {
  double rms = 0.0;  ///< root mean square keypoint distance (m)
  double max = 0.0;  ///< the largest keypoint distance (m)
};

/// One human grasp: the hypothesis it comes from, the hand pose and joints it closed to, the
/// stability suite's verdict and the winding values of the four hand curves around the object's
/// centre of mass. Poses are in the object frame.
struct HumanGrasp {
  int id = 0;
  GraspHypothesis hypothesis;
  bool reached = false;  ///< the approach touched the object (else nothing was simulated)
  Eigen::Isometry3d hand_pose = Eigen::Isometry3d::Identity();  ///< the palm (root link) pose
  Vec<20> q = Vec<20>::Zero();                                  ///< joints when closing ended
  ClosingRecord closing;                  ///< what closing did (the object's motion, contacts)
  StabilityResult stability;              ///< the deciding judge's verdict and records
  std::optional<StabilityResult> second;  ///< the other judge's, if there is one
  QualityRecord quality;                  ///< Ferrari-Canny epsilon when closing ended
  Vec<4> windings = Vec<4>::Zero();       ///< w of gamma_1 (index) .. gamma_4 (pinky)
  WindingDescriptor descriptor;           ///< the two largest, which curves
  /// Where the object was when closing ended (it starts at the identity).
  Eigen::Isometry3d object_pose = Eigen::Isometry3d::Identity();
  /// A recorded demonstration's fit to its keypoints (demonstrate_recorded()); empty for a
  /// planned one.
  std::optional<FitError> fit_error;
  [[nodiscard]] bool stable() const noexcept { return reached && stability.stable; }
};

/// What the judges say of a closed grasp: the deciding verdict, the other one, its quality.
struct GraspJudgement {
  StabilityResult stability;
  std::optional<StabilityResult> second;
  QualityRecord quality;
};

/// The reason a judge's hard-shake record gives when another engine decides (judge_grasp).
inline constexpr std::string_view k_hard_shake_deciding_only =
    "not run (the engine that decides runs the hard shake)";

/// Judges the grasp that \p scene holds as closing left it: the stability suite in the built-in
/// stepper, the second judge \p second (if any) with the same options, whichever
/// options.second_judge_decides names decides; and the Ferrari-Canny epsilon of its contacts
/// (where qhull is linked), torques scaled by the object's max radius from its centre of mass.
/// The hard shake (a stress reported apart, never part of the verdict) runs in the engine that
/// decides only, unless options.stability.every_test: the other's record has steps 0 and the
/// reason k_hard_shake_deciding_only.
/// Throws as stability_suite() for bad options.stability.
template <const auto& M>
[[nodiscard]] GraspJudgement judge_grasp(const HandScene<M>& scene, const GraspObject& object,
                                         const GraspSimOptions& options,
                                         const SecondJudge<M>& second) {
  GraspJudgement j;
  StabilityOptions builtin = options.stability, other = options.stability;
  const bool one_hard_shake = second && !options.stability.every_test;
  if (one_hard_shake) (options.second_judge_decides ? builtin : other).hard_shake.steps = 0;
  j.stability = stability_suite(scene, builtin);
  if (second) {
    j.second = second(scene, other);
    if (options.second_judge_decides) std::swap(j.stability, *j.second);
    if (one_hard_shake && options.stability.hard_shake.steps > 0)
      j.second->tests[k_stability_tests - 1].reason = k_hard_shake_deciding_only;
  }
#ifdef TOPOGRASP_HAVE_QHULL
  const std::vector<ContactForQuality> contacts = scene.hand_contact_points();
  j.quality.torque_scale = max_radius(object.parts, object.centre_of_mass());
  const GraspQuality q =
      ferrari_canny_epsilon(contacts, scene.object_com(), j.quality.torque_scale);
  j.quality.computed = true;
  j.quality.epsilon = q.epsilon;
  j.quality.status = std::string(to_string(q.status));
  j.quality.reason = q.reason;
#else
  (void)object;
#endif
  return j;
}

/// The contact surface of hand model \p M, by its name: the human hand's skin, the Barrett's
/// links, and the SDH's pads (also for any other model: its pads are the only robot surface with
/// a friction row of its own; docs/objects.md).
template <const auto& M>
[[nodiscard]] constexpr HandSurface hand_surface() noexcept {
  if (M.name.view() == "human_hand") return HandSurface::human_skin;
  if (M.name.view() == "barrett_bh8") return HandSurface::barrett;
  return HandSurface::sdh_pad;
}

/// The object as the physics scene wants it, at the object-frame origin, held by a hand of
/// surface \p hand: its parts' densities, and their friction against that hand from the table
/// of materials (friction_coefficient()), or \p friction for every part when it is positive.
/// An object without materials keeps its mass spread evenly and leaves the friction to
/// HandSceneOptions::friction (or takes \p friction). Throws topograsp::invalid_argument naming
/// "friction" for a negative or non-finite \p friction, and as GraspObject::validate() for a bad
/// object.
[[nodiscard]] inline ObjectSpec object_spec(const GraspObject& object, HandSurface hand,
                                            double friction = 0.0) {
  require_non_negative(friction, "friction");
  object.validate();
  ObjectSpec spec{object.parts, Pose{}, object.mass, 0.0};
  spec.part_density = object.densities;
  spec.inertial = object.inertial;
  if (friction > 0.0)
    spec.part_friction.assign(object.parts.size(), friction);
  else
    spec.part_friction = object.part_friction(hand);
  return spec;
}

/// A human grasp as closing left it: the free-base hand where the approach touched the object
/// (its 6 base coordinates, then the 20 joints of the pre-shape), the scene holding the object
/// and what closing did.
struct HumanClosing {
  Vec<26> touched = Vec<26>::Zero();
  HandScene<models::human_hand> scene;
  CloseResult<20> closing;
};

namespace detail {

// The human hand on its free base at `touched` (6 base coordinates, then the joints it closes
// from) closed on `object` with the human hand's holding torques (options.human_hold_fraction).
template <class = void>
HumanClosing close_human_at(const GraspObject& object, const Vec<26>& touched,
                            const GraspSimOptions& options) {
  KinematicsData<models::human_hand_free> d;
  forward_kinematics(d, touched);
  HandScene<models::human_hand> scene(
      link_pose(d, models::human_hand_free.link("palm")), touched.tail<20>(),
      object_spec(object, HandSurface::human_skin, options.friction), options.scene);
  CloseOptions close = options.close;
  close.hold_fraction = options.human_hold_fraction;
  close.max_grip = options.human_max_grip;
  const CloseResult<20> closing = close_hand(scene, close);
  return HumanClosing{touched, std::move(scene), closing};
}

// The demonstration `closed` judged into g (reached, pose, joints, the judges' verdicts, the
// windings of the closed hand around the object's centre of mass).
template <class = void>
void judge_human_closing(const GraspObject& object, const HumanClosing& closed,
                         const GraspSimOptions& options, HumanGrasp& g) {
  const HandScene<models::human_hand>& scene = closed.scene;
  g.reached = true;
  g.hand_pose = scene.hand_pose();
  g.q = closed.closing.q_closed;
  g.closing = closing_record(closed.closing);
  g.object_pose = scene.object_pose();
  GraspJudgement judged = judge_grasp(scene, object, options, options.second_judge_human);
  g.stability = std::move(judged.stability);
  g.second = std::move(judged.second);
  g.quality = std::move(judged.quality);
  Vec<26> qc = closed.touched;
  qc.tail<20>() = g.q;
  KinematicsData<models::human_hand_free> d;
  forward_kinematics(d, qc);
  const Vec3 com = object.centre_of_mass();
  g.windings = WindingTask<models::human_hand_free>(com).value(d);
  g.descriptor = winding_descriptor(d, com);
}

}  // namespace detail

/// Places the human hand's palm for hypothesis \p h of \p object (open pre-shape, at the
/// stand-off), approaches until contact and closes with the human hand's holding torques
/// (options.human_hold_fraction): the grasp demonstrate() judges, for a caller that wants the
/// scene itself (a benchmark, a figure, another judge). nullopt when the approach does not
/// reach the object. Throws as close_hand() for bad options.close.
template <class = void>
[[nodiscard]] std::optional<HumanClosing> close_human_grasp(const GraspObject& object,
                                                            const GraspHypothesis& h,
                                                            const GraspSimOptions& options = {}) {
  const Composite shape = object.composite();
  const Vec<20> pre = human_preshape();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = palm_rotation(human_hand_axes, h.approach, h.up);
  T.translation() = h.centre - options.standoff * h.approach;
  const Vec<26> start =
      place_frame<models::human_hand_free>(T, models::human_hand_free.frame("grasp_centre"), pre);
  constexpr auto& free = models::human_hand_free;
  PalmApproachOptions palm_approach;
  palm_approach.gap = options.contact_gap;
  palm_approach.max_travel = 2.0 * options.standoff;
  const auto touched =
      options.palm_first
          ? approach_palm_first<free>(start, h.approach, shape, free.link("palm"), palm_approach)
          : approach_until_contact<free>(start, h.approach, shape, options.contact_gap,
                                         2.0 * options.standoff);
  if (!touched) return std::nullopt;
  return detail::close_human_at(object, *touched, options);
}

/// Runs hypothesis \p h of \p object with the human hand: place the palm (open pre-shape) at the
/// stand-off, approach until contact, close (close_human_grasp()), then the stability suite on
/// the scene as closing left it: the grasp is a demonstration only if stable(). Deterministic
/// for given options. Throws as stability_suite() for bad options.stability.
template <class = void>
[[nodiscard]] HumanGrasp demonstrate(const GraspObject& object, const GraspHypothesis& h, int id,
                                     const GraspSimOptions& options = {}) {
  HumanGrasp g;
  g.id = id;
  g.hypothesis = h;
  const std::optional<HumanClosing> closed = close_human_grasp(object, h, options);
  if (closed) detail::judge_human_closing(object, *closed, options, g);
  return g;
}

#ifdef TOPOGRASP_EXTERN_HAND_INDEPENDENT
// Compiled once, in the one translation unit that includes grasp/hand_independent.hpp
// (docs/benchmarks.md, "Compiling the transfer once per program").
extern template HumanGrasp demonstrate<void>(const GraspObject&, const GraspHypothesis&, int,
                                             const GraspSimOptions&);
#endif

}  // namespace topograsp
