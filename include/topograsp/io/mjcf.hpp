// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// MJCF export of a hand scene, so a grasp can be re-checked in MuJoCo (2.2 or later): the hand
/// articulated (joints, motors, couplings, the grasp as a keyframe). A World with its hand frozen:
/// io/mjcf_world.hpp, included here.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <string>
#include <string_view>
#include <type_traits>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/evaluation/hand_scene.hpp>
#include <topograsp/io/detail/mjcf_write.hpp>
#include <topograsp/io/mjcf_world.hpp>
#include <topograsp/physics/world.hpp>

namespace topograsp {

/// The settings of the articulated MJCF export of a hand scene (write_mjcf(os, HandScene, ...)).
/// Every value has a physical or numerical reason, given with it; docs/evaluation.md gathers them.
struct MjcfOptions {
  /// The largest MuJoCo time step (s): the scene's own time step is split into the fewest equal
  /// MuJoCo steps not longer than this. Grasps need 2 ms or less (MuJoCo's contacts are soft over
  /// a few steps; longer steps let a held object sink and creep). Default 0.002.
  double max_time_step = 0.002;
  /// MuJoCo's impratio: the ratio of frictional to normal constraint impedance. 10 or more with
  /// elliptic cones keeps a held object from creeping out of the grip. Default 10.
  double impratio = 10.0;
  /// The rotor inertia (kg m^2 or kg) written for a joint whose model gives none
  /// (LinkSpec::armature 0): without it a light finger link on a stiff position servo is beyond
  /// what a 2 ms explicit spring step resolves. Default 0.001.
  double default_armature = 0.001;
  /// Contacts are reported (mjData::contact, MujocoScene::hand_contacts) out to this distance (m)
  /// and act only on overlap: each pair gets margin = gap = this value, so MuJoCo's constraint
  /// starts at distance 0 exactly as without it. Default 0: MuJoCo 2.2 measures pairs with a
  /// cylinder by its general convex collider (MPR), which runs on the shapes grown by the
  /// margin and with any margin can report wrong depths (docs/evaluation.md);
  /// MujocoScene::collider_error() measures this per grasp.
  double report_distance = 0.0;
  /// The time constant (s) of every hand-object contact (the pair's solref, damping ratio 1): the
  /// contact's stiffness is about the effective mass / timeconst^2. At least 2 time steps, as
  /// MuJoCo asks. Default 0.01, near the built-in finger pads' stiffness (docs/evaluation.md).
  double contact_timeconst = 0.01;
  /// The time constant (s) of the weld that makes the hand's base follow the mocap body `hand`
  /// (solref, damping ratio 1): the shorter, the stiffer. At least 2 * max_time_step, as MuJoCo
  /// asks. Default 0.004.
  double hand_timeconst = 0.004;
  /// Whether MuJoCo's general convex collider (every pair with a cylinder or a mesh in MuJoCo
  /// 2.2: the palm on a handle, a finger on a bottle) returns several contact points per pair
  /// (`<flag multiccd="enable"/>`) instead of one. With one, the contact between a palm and a
  /// handle resists a turn only by its torsional friction, where the built-in stepper's manifold
  /// (and a real palm) spreads it over the contact patch: MuJoCo let held hammers turn 0.3 to 0.8
  /// rad under gravity that the built-in held within 0.1 (docs/evaluation.md). Default true.
  bool multi_point_contacts = true;
  /// Iterations of MuJoCo's noslip solver (`noslip_iterations`; 0: off), which after the main
  /// solver removes the slip that MuJoCo's soft friction constraints let a contact below its
  /// friction limit make. The built-in stepper's friction sticks below the cone (creeping under 1
  /// mm/s, docs/stepper.md); without noslip MuJoCo's friction creeps, more the harder the grip, and
  /// let objects slide and turn out of grips the built-in held within millimetres
  /// (docs/evaluation.md). Default 10, in [0, 1000].
  int noslip_iterations = 10;
  /// Overrides the effort limit of each configuration entry (N m or N, dim nq, each > 0); empty:
  /// the model's LinkSpec::effort.
  std::vector<double> effort;
};

namespace detail {

/// What the articulated export reads of a hand scene's motors: the joints' actual values, their
/// targets, each configuration entry's effort limit (N m or N) and the fraction of it the motors
/// may give now.
template <int NQ>
struct MjcfMotorState {
  Vec<NQ> q = Vec<NQ>::Zero();
  Vec<NQ> target = Vec<NQ>::Zero();
  std::array<double, static_cast<std::size_t>(NQ)> effort{};
  double fraction = 1.0;
};

/// Reads the motor state of \p scene: the joints' positions and targets, the model's efforts
/// (or options.effort when given) and the fraction of them the motors may give now.
template <const auto& M, class S>
MjcfMotorState<M.nq> mjcf_motor_state(const HandScene<M, S>& scene, const MjcfOptions& options) {
  MjcfMotorState<M.nq> out;
  out.q = scene.joint_positions();
  out.target = scene.joint_targets();
  out.fraction = scene.effort_fraction();
  for (int i = 0; i < M.nq; ++i)
    out.effort[static_cast<std::size_t>(i)] = options.effort.empty()
                                                  ? M.joint_spec(i).effort
                                                  : options.effort[static_cast<std::size_t>(i)];
  return out;
}

inline void require_mjcf_options(const MjcfOptions& o, int nq) {
  require_positive(o.max_time_step, "options.max_time_step");
  require_positive(o.impratio, "options.impratio");
  require_non_negative(o.default_armature, "options.default_armature");
  require_non_negative(o.report_distance, "options.report_distance");
  if (o.noslip_iterations < 0 || o.noslip_iterations > 1000)
    throw_invalid_argument("options.noslip_iterations",
                           "expected 0 to 1000, got " + std::to_string(o.noslip_iterations));
  const auto require_timeconst = [&](double t, const char* name) {
    if (!(t >= 2.0 * o.max_time_step && t < 1e3))
      throw_invalid_argument(name,
                             "expected at least 2 time steps (2 * options.max_time_step) and under "
                             "1000 s, got " +
                                 std::to_string(t));
  };
  require_timeconst(o.contact_timeconst, "options.contact_timeconst");
  require_timeconst(o.hand_timeconst, "options.hand_timeconst");
  if (!o.effort.empty() && static_cast<int>(o.effort.size()) != nq)
    throw_invalid_argument("options.effort", "expected " + std::to_string(nq) +
                                                 " entries (one per configuration entry) or none, "
                                                 "got " +
                                                 std::to_string(o.effort.size()));
  for (std::size_t i = 0; i < o.effort.size(); ++i)
    require_positive(o.effort[i], "options.effort[" + std::to_string(i) + "]");
}

}  // namespace detail

/// The number of MuJoCo steps that make one step of \p time_step (s) with steps of at most
/// \p max_time_step (s): the fewest such steps (at least 1).
[[nodiscard]] inline int mjcf_substeps(double time_step, double max_time_step) {
  require_positive(time_step, "time_step");
  require_positive(max_time_step, "max_time_step");
  const double n = std::ceil(time_step / max_time_step * (1.0 - 1e-12));
  if (!(n <= 1e6))
    detail::throw_invalid_argument("max_time_step", "expected at least time_step / 1e6");
  return std::max(1, static_cast<int>(n));
}

/// Writes \p scene as an articulated MJCF model that MuJoCo 2.2 loads and that opens holding the
/// object (the scene contract of docs/evaluation.md):
/// - `<option>`: the scene's time step split into mjcf_substeps(time_step, max_time_step) equal
///   steps, the scene's gravity, `cone="elliptic"`, options.impratio, `integrator="implicit"`,
///   the multiccd flag (options.multi_point_contacts), options.noslip_iterations when positive;
/// - a mocap body named `hand` at the hand frame (the target the scene moves) and the hand's
///   base, a body named `hand_base` with a free joint (the model's root link: its shapes and
///   mass), held to `hand` by a weld equality (solref options.hand_timeconst, damping ratio 1).
///   A mocap body has no velocity in MuJoCo: shapes carried by one would jump from step to step
///   and drag nothing by friction, where the welded base moves with the velocity the built-in
///   stepper gives its kinematic hand. Nested in the base, every other link as a body (named as
///   the link) at its joint origin, with its joint (hinge or slide about the model's axis,
///   `range` = limits, `armature` = LinkSpec::armature or options.default_armature when 0,
///   `damping` = kv) and its shapes;
/// - link inertia: LinkSpec mass at LinkSpec com with the inertia of a uniform sphere of that
///   mass reaching the link's farthest shape point; a link of mass 0 (no data) gets its inertia
///   from its shapes at MuJoCo's default density (1000 kg/m^3), a link with neither is bounded by
///   `boundmass` 1e-4 kg and `boundinertia` 1e-9 kg m^2;
/// - one `<position>` actuator per configuration entry on its joint, `ctrlrange` = the joint
///   limits, `forcerange` = +-(effort x fraction), and the built-in servo's spring: `kp` =
///   HandScene::servo_stiffness() (effort / servo_reach(), times the fraction above 1) and the
///   joint's damping kp x HandSceneOptions::servo_damping_time (MuJoCo 2.2's position actuator has
///   no kv; the joint damping is integrated implicitly); with effort 0 (the model gives none and
///   options.effort is empty) the actuator is written without a force range and with kp = 1 /
///   reach, and an XML comment says so;
/// - mimic joints as `<equality><joint joint1="mimic" joint2="source" polycoef="offset
///   multiplier 0 0 0"/>`;
/// - the object as a body named `object` with a free joint, its World mass, centre of mass and
///   full inertia, and its shapes;
/// - no contact by geom type (contype = conaffinity = 0): one `<contact><pair>` per (hand shape,
///   object shape) with the World's pair friction (World::manifolds()[k].friction, so the
///   coefficient is exact whatever MuJoCo's combination rule), condim 4 with torsional friction
///   mu x torsional_friction_radius (3 without), margin = gap = options.report_distance, solref
///   = options.contact_timeconst with damping ratio 1;
/// - a site named `palm` at the model's palm centre (a hand model only);
/// - `<keyframe><key name="grasp">` with qpos (the base's pose, the joints' values and the
///   object's pose), ctrl (the targets, clamped to the limits), mpos and mquat (the hand pose).
/// Geoms are named `hand_<collider>` (the World's collider index) and `object_<k>`.
/// \throws topograsp::invalid_argument naming the option for a bad option (non-positive
/// max_time_step or impratio; negative default_armature or report_distance; noslip_iterations
/// outside [0, 1000]; a contact_timeconst
/// or hand_timeconst under 2 * max_time_step; options.effort of the wrong size or with an entry
/// that is not positive).
template <const auto& M, class S>
void write_mjcf(std::ostream& os, const HandScene<M, S>& scene, const MjcfOptions& options) {
  using ModelType = std::remove_cvref_t<decltype(M)>;
  constexpr int NL = static_cast<int>(ModelType::n_links);
  detail::require_mjcf_options(options, M.nq);
  const auto motors = detail::mjcf_motor_state(scene, options);
  const World<S>& world = scene.world();
  const StepperOptions& so = world.options();
  const int substeps = mjcf_substeps(so.time_step, options.max_time_step);
  const double torsion = so.torsional_friction_radius;

  const auto flags = os.flags();
  const auto precision = os.precision();
  os << std::setprecision(17);  // round trip: the keyframe reproduces the scene exactly
  os << "<mujoco model=\"" << M.name.view() << "\">\n";
  os << "  <compiler angle=\"radian\" inertiafromgeom=\"auto\" boundmass=\"1e-4\" "
        "boundinertia=\"1e-9\"/>\n";
  os << "  <option timestep=\"" << so.time_step / substeps << '"';
  detail::write_mjcf_vec3(os, "gravity", world.gravity().template cast<double>());
  os << " cone=\"elliptic\" impratio=\"" << options.impratio << "\" integrator=\"implicit\"";
  if (options.noslip_iterations > 0)
    os << " noslip_iterations=\"" << options.noslip_iterations << '"';
  os << (options.multi_point_contacts ? ">\n    <flag multiccd=\"enable\"/>\n  </option>\n"
                                      : "/>\n");
  os << "  <size nkey=\"1\"/>\n";
  os << "  <default>\n    <geom contype=\"0\" conaffinity=\"0\"/>\n  </default>\n";

  // Per joint: kp, kv and the force limit (0: none) of the actuator that drives it.
  std::array<double, static_cast<std::size_t>(M.nq)> kp{}, limit{};
  for (int i = 0; i < M.nq; ++i) {
    const auto u = static_cast<std::size_t>(i);
    // The built-in servo's stiffness: the full effort at the scene's servo reach.
    const double hold = scene.servo_reach(i);
    limit[u] = motors.effort[u] * motors.fraction;
    kp[u] =
        std::max(1.0, motors.fraction) * (motors.effort[u] > 0.0 ? motors.effort[u] : 1.0) / hold;
  }
  const auto joint_value = [&](int l) {
    const Link& link = M.links[static_cast<std::size_t>(l)];
    const double q = motors.q[link.q];
    return link.spec.mimic.empty() ? q : link.spec.multiplier * q + link.spec.offset;
  };
  // Bodies depth first; MuJoCo numbers the joints in this order, so the keyframe follows it.
  std::vector<int> joint_order;
  std::vector<std::string> hand_geoms;
  const auto write_body = [&](const auto& self, int l, int depth) -> void {
    const Link& link = M.links[static_cast<std::size_t>(l)];
    const std::string indent(static_cast<std::size_t>(2 * depth + 4), ' ');
    if (l == 0) {
      // The target (mocap, no geoms) and the hand's base, a free body welded to it: a mocap
      // body has no velocity in MuJoCo, so a hand carried by one would move its contacts
      // without dragging the object by friction.
      os << indent << "<body name=\"hand\" mocap=\"true\"";
      detail::write_mjcf_pose(os, scene.hand_pose());
      os << "/>\n" << indent << "<body name=\"hand_base\"";
      detail::write_mjcf_pose(os, scene.hand_pose());
      os << ">\n" << indent << "  <joint name=\"hand_base\" type=\"free\"/>\n";
    } else {
      os << indent << "<body name=\"" << link.spec.name.view() << '"';
      detail::write_mjcf_pose(os, link.spec.origin.isometry());
      os << ">\n";
    }
    const std::string in = indent + "  ";
    if (link.spec.mass > 0.0) {
      const Vec3 c(link.spec.com[0], link.spec.com[1], link.spec.com[2]);
      double r = 0.0;
      for (const Shape& s : M.shapes)
        if (s.link == l)
          r = std::max(r, (s.spec.pose.isometry().translation() - c).norm() +
                              detail::mjcf_shape_radius(s.spec));
      if (!(r > 0.0)) r = 0.01;  // no shapes: a 1 cm sphere
      const double I = 0.4 * link.spec.mass * r * r;
      os << in << "<inertial";
      detail::write_mjcf_vec3(os, "pos", c);
      os << " mass=\"" << link.spec.mass << "\" diaginertia=\"" << I << ' ' << I << ' ' << I
         << "\"/>\n";
    }
    if (link.spec.type != JointType::fixed) {
      joint_order.push_back(l);
      const auto src = static_cast<std::size_t>(link.q);
      const LinkSpec& owner = M.joint_spec(link.q);
      const double armature = owner.armature > 0.0 ? owner.armature : options.default_armature;
      const double scale = link.spec.mimic.empty() ? 1.0 : std::abs(link.spec.multiplier);
      os << in << "<joint name=\"" << link.spec.name.view() << "\" type=\""
         << (link.spec.type == JointType::prismatic ? "slide" : "hinge") << '"';
      detail::write_mjcf_vec3(os, "axis", Vec3(link.axis[0], link.axis[1], link.axis[2]));
      os << " limited=\"true\" range=\"" << link.spec.lower << ' ' << link.spec.upper
         << "\" armature=\"" << armature << "\" damping=\""
         << kp[src] * scene.options().servo_damping_time * scale << "\"/>\n";
    }
    const int body = scene.link_body(l);
    if (body >= 0) {
      const RigidBody<S>& b = world.body(body);
      for (int c = b.first_collider; c < b.first_collider + b.n_colliders; ++c) {
        hand_geoms.push_back("hand_" + std::to_string(c));
        os << in << "<geom name=\"" << hand_geoms.back() << '"';
        detail::write_mjcf_shape(os, world.collider(c).spec);
        detail::write_mjcf_pose(os, world.collider(c).spec.pose.isometry());
        os << "/>\n";
      }
    }
    if constexpr (M.is_hand())
      if (M.palm.link == l) {
        os << in << "<site name=\"palm\"";
        detail::write_mjcf_vec3(os, "pos",
                                Vec3(M.palm.offset[0], M.palm.offset[1], M.palm.offset[2]));
        os << " size=\"0.005\"/>\n";
      }
    for (int j = l + 1; j < NL; ++j)
      if (M.links[static_cast<std::size_t>(j)].parent == l) self(self, j, depth + 1);
    os << indent << "</body>\n";
  };
  os << "  <worldbody>\n";
  write_body(write_body, 0, 0);
  const RigidBody<S>& object = world.body(scene.object_body());
  os << "    <body name=\"object\"";
  detail::write_mjcf_pose(os, object.pose());
  os << ">\n      <joint name=\"object_free\" type=\"free\"/>\n";
  {
    const Mat3 I = object.inertia.template cast<double>();
    os << "      <inertial";
    detail::write_mjcf_vec3(os, "pos", object.local_com.template cast<double>());
    os << " mass=\"" << static_cast<double>(object.mass) << "\" fullinertia=\"" << I(0, 0) << ' '
       << I(1, 1) << ' ' << I(2, 2) << ' ' << I(0, 1) << ' ' << I(0, 2) << ' ' << I(1, 2)
       << "\"/>\n";
  }
  for (int k = 0; k < object.n_colliders; ++k) {
    const auto& spec = world.collider(object.first_collider + k).spec;
    os << "      <geom name=\"object_" << k << '"';
    detail::write_mjcf_shape(os, spec);
    detail::write_mjcf_pose(os, spec.pose.isometry());
    os << "/>\n";
  }
  os << "    </body>\n  </worldbody>\n";

  os << "  <contact>\n";
  for (const Manifold<S>& m : world.manifolds()) {
    const bool a_is_object = m.body_a == scene.object_body();
    if (!a_is_object && m.body_b != scene.object_body()) continue;
    const int hand_collider = a_is_object ? m.collider_b : m.collider_a;
    const int object_collider = (a_is_object ? m.collider_a : m.collider_b) - object.first_collider;
    if (world.body(world.collider(hand_collider).body).type != BodyType::kinematic) continue;
    const double mu = static_cast<double>(m.friction);
    os << "    <pair geom1=\"hand_" << hand_collider << "\" geom2=\"object_" << object_collider
       << "\" condim=\"" << (torsion > 0.0 ? 4 : 3) << "\" friction=\"" << mu << ' ' << mu << ' '
       << mu * torsion << " 0.0001 0.0001\" margin=\"" << options.report_distance << "\" gap=\""
       << options.report_distance << "\" solref=\"" << options.contact_timeconst << " 1\"/>\n";
  }
  os << "  </contact>\n";

  os << "  <equality>\n    <weld name=\"hand_base\" body1=\"hand_base\" body2=\"hand\" solref=\""
     << options.hand_timeconst << " 1\"/>\n";
  for (const Link& l : M.links)
    if (l.spec.type != JointType::fixed && !l.spec.mimic.empty())
      os << "    <joint joint1=\"" << l.spec.name.view() << "\" joint2=\"" << l.spec.mimic.view()
         << "\" polycoef=\"" << l.spec.offset << ' ' << l.spec.multiplier << " 0 0 0\"/>\n";
  os << "  </equality>\n";

  os << "  <actuator>\n";
  for (int i = 0; i < M.nq; ++i) {
    const auto u = static_cast<std::size_t>(i);
    const LinkSpec& j = M.joint_spec(i);
    if (!(limit[u] > 0.0))
      os << "    <!-- no effort limit for " << j.name.view()
         << " (LinkSpec::effort is 0): kp = 1 / hold, no force range -->\n";
    os << "    <position name=\"" << j.name.view() << "\" joint=\"" << j.name.view() << "\" kp=\""
       << kp[u] << "\" ctrllimited=\"true\" ctrlrange=\"" << j.lower << ' ' << j.upper << '"';
    if (limit[u] > 0.0)
      os << " forcelimited=\"true\" forcerange=\"" << -limit[u] << ' ' << limit[u] << '"';
    os << "/>\n";
  }
  os << "  </actuator>\n";

  const Eigen::Isometry3d& T_hand = scene.hand_pose();
  const Eigen::Quaterniond q_hand(T_hand.linear());
  os << "  <keyframe>\n    <key name=\"grasp\" qpos=\"" << T_hand.translation().x() << ' '
     << T_hand.translation().y() << ' ' << T_hand.translation().z() << ' ' << q_hand.w() << ' '
     << q_hand.x() << ' ' << q_hand.y() << ' ' << q_hand.z() << ' ';
  for (const int l : joint_order) os << joint_value(l) << ' ';
  const Eigen::Isometry3d T_object = object.pose();
  const Eigen::Quaterniond q_object(T_object.linear());
  os << T_object.translation().x() << ' ' << T_object.translation().y() << ' '
     << T_object.translation().z() << ' ' << q_object.w() << ' ' << q_object.x() << ' '
     << q_object.y() << ' ' << q_object.z() << "\" ctrl=\"";
  for (int i = 0; i < M.nq; ++i) {
    const LinkSpec& j = M.joint_spec(i);
    os << (i > 0 ? " " : "") << std::clamp(motors.target[i], j.lower, j.upper);
  }
  os << '"';
  detail::write_mjcf_vec3(os, "mpos", T_hand.translation());
  os << " mquat=\"" << q_hand.w() << ' ' << q_hand.x() << ' ' << q_hand.y() << ' ' << q_hand.z()
     << "\"/>\n  </keyframe>\n</mujoco>\n";
  os.flags(flags);
  os.precision(precision);
}

/// Writes the hand scene \p scene as articulated MJCF with default MjcfOptions; see
/// write_mjcf(std::ostream&, const HandScene<M, S>&, const MjcfOptions&).
template <const auto& M, class S>
void write_mjcf(std::ostream& os, const HandScene<M, S>& scene) {
  write_mjcf(os, scene, MjcfOptions{});
}

/// The articulated MJCF text of \p scene (write_mjcf; throws as it does).
template <const auto& M, class S>
[[nodiscard]] std::string to_mjcf(const HandScene<M, S>& scene, const MjcfOptions& options = {}) {
  std::ostringstream os;
  write_mjcf(os, scene, options);
  return os.str();
}

}  // namespace topograsp
