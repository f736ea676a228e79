// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// HandScene: a World holding a hand whose joints are driven by torque-limited motors (joint-space
/// actuators of the World; the links are kinematic bodies placed at the forward kinematics of the
/// actuators' positions) and an object made of shapes as a dynamic body.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdio>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <topograsp/core/number_text.hpp>
#include <topograsp/evaluation/grasp_wrench.hpp>
#include <topograsp/evaluation/object_spec.hpp>
#include <topograsp/geometry/mass_properties.hpp>
#include <topograsp/kinematics/data.hpp>
#include <topograsp/kinematics/forward.hpp>
#include <topograsp/kinematics/jacobian.hpp>
#include <topograsp/physics/body_contacts.hpp>
#include <topograsp/physics/world.hpp>

namespace topograsp {

/// The parameters of a HandScene beyond the stepper's.
struct HandSceneOptions {
  /// Time step, contact stiffness, ...: StepperOptions defaults but 4 solver iterations (light
  /// finger joints on a heavy object converge poorly in one, StepperOptions::iterations) and
  /// finger pads of 8000 N/m (kinematic_stiffness: firm rubber pads, 8 N per mm, so that a finger
  /// pressing with 10 to 20 N gives 1 to 3 mm).
  StepperOptions stepper = [] {
    StepperOptions o;
    o.iterations = 4;
    o.kinematic_stiffness = 8000.0;
    return o;
  }();
  /// Coulomb friction coefficient between the hand and the object. Default 1 (rubber-covered
  /// fingers on plastic or wood are about 0.8 to 1.2).
  double friction = 1.0;
  /// How far from its target a motor gives its full torque limit (rad): each servo's stiffness
  /// is the joint's effort / servo_angle (N m/rad), as MuJoCo's position actuator kp. Default
  /// 0.05 rad (3 degrees): a stiff position servo.
  double servo_angle = 0.05;
  /// The same for prismatic joints (m). Default 0.005 m.
  double servo_distance = 0.005;
  /// Each servo's damping is its stiffness times this (s). Default 0.01 s.
  double servo_damping_time = 0.01;
};

/// One hand-object contact point (HandScene::hand_contact_list()).
struct HandContact {
  std::string link;             ///< the name of the link it is on
  Vec3 point = Vec3::Zero();    ///< the contact point (m; world frame, or as its holder says)
  Vec3 normal = Vec3::UnitZ();  ///< unit, pointing into the object
  double force = 0.0;           ///< the normal force it carried over the last step (N)
  double friction = 0.0;        ///< the Coulomb coefficient of its pair of shapes
};

/// The largest multiple of a joint's effort (LinkSpec::effort) a hand scene's motor may give
/// (HandScene::set_effort_fraction()).
inline constexpr double k_max_effort_fraction = 10.0;

/// A hand of model \p M (a reference to a constexpr Model) holding an object, over scalar \p S.
///
/// The hand frame (the model's root link) is carried to hand_pose() like a mocap body. Each
/// configuration entry (an actuated joint, with its mimic joints) is a joint-space actuator of
/// the World: a servo with the joint's torque limit (LinkSpec::effort, scaled by
/// effort_fraction()), speed limit (LinkSpec::velocity) and limits, whose inertia is the
/// diagonal of the hand's joint-space inertia at the current configuration (link masses and
/// centres of mass, LinkSpec::inertial(); each link's rotational inertia from its shapes) plus the
/// rotor's (LinkSpec::armature), and which carries the weight of the links it moves. Contacts on
/// a link push back on the actuators of its chain, so a finger presses on the object with what
/// its motor gives and no more. Every link with shapes is a kinematic body of the World, moved
/// after each step to the forward kinematics of the actuators' positions. The model must give
/// every actuated joint an effort and a velocity limit; an actuator that moves no mass and has no
/// armature gets an inertia of 1e-5 kg m^2 (a light finger joint's).
template <const auto& M, class S = double>
  requires KinematicModel<decltype(M)>
class HandScene {
 public:
  using ModelType = std::remove_cvref_t<decltype(M)>;
  static constexpr int nq = M.nq;
  using Config = Vec<nq>;
  static_assert(
      [] {
        for (const auto& s : M.supports)
          if (s.size > k_max_body_joints) return false;
        return true;
      }(),
      "a HandScene carries each link on at most k_max_body_joints joints");

  /// Builds the scene: the hand frame at \p hand_pose with joints at \p q clamped to the model's
  /// limits (also the motors' targets; the motors at their full torque limit), and the object.
  /// Throws topograsp::invalid_argument naming the argument for a non-finite or wrongly sized
  /// q, a bad pose (as set_hand_pose()), an object the World refuses (its ranges; named as the
  /// object's field, e.g. "object.mass", "object.shapes[0].size[0]"), an object without shapes,
  /// a bad shape, a non-positive mass (or density when the mass is 0 and no part densities are
  /// given), a part_density or part_friction whose size is not the number of shapes
  /// ("object.part_density", "object.part_friction") or with an entry that is not positive and
  /// finite (part_density) or not in [0, 1e6] (part_friction), named with its index, an inertial
  /// that is not physical ("object.inertial.mass", ".com", ".inertia"), or bad options; and naming
  /// "model" for a model whose actuated joint has no effort or velocity limit. part_friction is set
  /// on every pair of a hand link's shape and that part.
  HandScene(const Eigen::Isometry3d& hand_pose, const Config& q, const ObjectSpec& object,
            const HandSceneOptions& options = {})
      : world_(options.stepper), options_(options) {
    require_configuration<M>(q, "q");
    require_hand_pose(hand_pose, "hand_pose");
    require_positive(options.friction, "options.friction");
    require_positive(options.servo_angle, "options.servo_angle");
    require_positive(options.servo_distance, "options.servo_distance");
    require_non_negative(options.servo_damping_time, "options.servo_damping_time");
    require_motors();
    detail::require_object_spec(object);
    hand_pose_ = placed_ = hand_pose;
    q_ = target_ = clamp_to_limits<M>(q);
    forward_kinematics(kin_, q_);
    link_inertia_.fill(Mat3::Zero());
    for (std::size_t l = 0; l < ModelType::n_links; ++l) {
      const LinkSpec& spec = M.links[l].spec;
      link_com_[l] = Vec3(spec.com[0], spec.com[1], spec.com[2]);
      std::vector<ShapeSpec> own;
      for (const Shape& sh : M.shapes)
        if (sh.link == static_cast<int>(l)) own.push_back(sh.spec);
      if (spec.mass > 0.0 && !own.empty())
        link_inertia_[l] = body_mass_properties<double>(own, spec.mass, 1000.0).inertia;
    }
    update_joint_space();
    for (int i = 0; i < nq; ++i) {
      const LinkSpec& spec = M.joint_spec(i);
      ActuatorDesc a;
      a.position = q_[i];
      a.lower = spec.lower;
      a.upper = spec.upper;
      a.inertia = inertia_[i];
      a.max_effort = M.joint_spec(i).effort;
      a.max_velocity = M.joint_spec(i).velocity;
      a.stiffness = servo_stiffness(i);
      a.damping_time = options.servo_damping_time;
      actuator_[static_cast<std::size_t>(i)] = world_.add_actuator(a);
    }
    link_body_.fill(-1);
    std::vector<ShapeSpec> link_shapes;
    for (std::size_t l = 0; l < ModelType::n_links; ++l) {
      link_shapes.clear();
      for (const Shape& s : M.shapes)
        if (s.link == static_cast<int>(l)) link_shapes.push_back(s.spec);
      if (link_shapes.empty()) continue;
      BodyDesc d;
      d.type = BodyType::kinematic;
      d.pose = to_pose(link_pose(static_cast<int>(l)));
      d.shapes = link_shapes;
      d.friction = options.friction;
      link_body_[l] = world_.add_body(d);
    }
    object_ = detail::add_object_body(world_, object, options.friction);
    // Friction per pair of materials: each part against every shape of every hand link.
    if (!object.part_friction.empty()) {
      const RigidBody<S>& ob = world_.body(object_);
      for (const int b : link_body_) {
        if (b < 0) continue;
        const RigidBody<S>& lb = world_.body(b);
        for (int c = lb.first_collider; c < lb.first_collider + lb.n_colliders; ++c)
          for (int k = 0; k < ob.n_colliders; ++k)
            world_.set_pair_friction(c, ob.first_collider + k,
                                     object.part_friction[static_cast<std::size_t>(k)]);
      }
    }
  }

  /// Sets the motors' targets (dim nq, rad or m). A target beyond a joint limit drives the joint
  /// to its limit; a finger commanded past the object stops on it, pressing with its torque
  /// limit. Throws topograsp::invalid_argument for non-finite entries.
  void set_joint_targets(const Config& q) {
    require_configuration<M>(q, "q");
    target_ = clamp_to_limits<M>(q);
    for (int i = 0; i < nq; ++i)
      world_.set_actuator_target(actuator_[static_cast<std::size_t>(i)], target_[i]);
  }
  /// Scales every motor's torque limit to \p fraction of the joint's effort (LinkSpec::effort):
  /// 1 to close, a stated fraction to hold (CloseOptions::hold_fraction); above 1 for a grip
  /// stronger than the model's efforts (CloseOptions::max_grip: the human hand's efforts are
  /// holding torques, not its strength), the servos then as much stiffer (servo_stiffness()), as
  /// a muscle stiffens in proportion to the force it gives. Throws topograsp::invalid_argument
  /// naming "fraction" unless it is in (0, k_max_effort_fraction].
  void set_effort_fraction(double fraction) {
    if (!(fraction > 0.0 && fraction <= k_max_effort_fraction))
      detail::throw_invalid_argument(
          "fraction",
          "expected a value in (0, " + detail::number_text(k_max_effort_fraction) + "]");
    effort_fraction_ = fraction;
    for (int i = 0; i < nq; ++i) {
      const int a = actuator_[static_cast<std::size_t>(i)];
      world_.set_actuator_max_effort(a, effort_limit(i));
      world_.set_actuator_gains(a, servo_stiffness(i), options_.servo_damping_time);
    }
  }
  /// The fraction of each joint's effort its motor may give now.
  [[nodiscard]] double effort_fraction() const noexcept { return effort_fraction_; }
  /// The torque limit (N m, or N) of configuration entry \p i's motor now.
  [[nodiscard]] double effort_limit(int i) const noexcept {
    return effort_fraction_ * M.joint_spec(i).effort;
  }
  /// The torque (N m, or N) configuration entry \p i's motor gave over the last step.
  [[nodiscard]] double motor_torque(int i) const noexcept {
    return world_.actuator_torque(actuator_[static_cast<std::size_t>(i)]);
  }
  /// How far from its target configuration entry \p i's motor gives its full torque limit
  /// (options().servo_angle, or servo_distance for a prismatic joint).
  [[nodiscard]] double servo_reach(int i) const noexcept {
    return M.joint_spec(i).type == JointType::prismatic ? options_.servo_distance
                                                        : options_.servo_angle;
  }
  /// The stiffness of configuration entry \p i's servo now (N m/rad, or N/m): its effort over
  /// servo_reach(), times the effort fraction where that is above 1.
  [[nodiscard]] double servo_stiffness(int i) const noexcept {
    return std::max(1.0, effort_fraction_) * M.joint_spec(i).effort / servo_reach(i);
  }
  /// The joints' positions (dim nq, rad or m): where the motors have taken them.
  [[nodiscard]] const Config& joint_positions() const noexcept { return q_; }
  /// The largest coordinate (m) of a hand pose: 1e6 m. Far beyond any workspace, and small
  /// enough that every link pose (the hand pose times a link's offset) stays within the World's
  /// max_length() for both double and float.
  static constexpr double k_max_hand_coordinate = 1e6;

  /// Sets the hand frame pose that the next step() drives the hand to. Throws
  /// topograsp::invalid_argument naming "pose" for a non-finite pose, a linear part that is not a
  /// rotation, or a coordinate above k_max_hand_coordinate.
  void set_hand_pose(const Eigen::Isometry3d& pose) {
    require_hand_pose(pose, "pose");
    hand_pose_ = pose;
  }
  /// Puts the hand at \p pose with joints at \p q (clamped to the limits) at once, at rest (no
  /// motion, no contact impulses), and makes them the motors' targets.
  void place_hand(const Eigen::Isometry3d& pose, const Config& q) {
    set_hand_pose(pose);
    set_joint_targets(q);
    placed_ = hand_pose_;
    q_ = target_;
    for (int i = 0; i < nq; ++i)
      world_.set_actuator_position(actuator_[static_cast<std::size_t>(i)], q_[i]);
    forward_kinematics(kin_, q_);
    for (std::size_t l = 0; l < ModelType::n_links; ++l)
      if (link_body_[l] >= 0) world_.set_pose(link_body_[l], link_pose(static_cast<int>(l)));
  }

  /// Advances the world by one step, allocating nothing: the hand frame moves to hand_pose()
  /// (each link with it, at the joints' positions), the motors drive the joints towards their
  /// targets within their torque limits while contacts push back, and the links are placed where
  /// the joints went. Returns the World's status (Status::numerical_issue ends the run). If a
  /// link pose at the new hand pose is not one the World accepts (World::target_in_range():
  /// non-finite, or beyond World::max_length()), nothing moves and the step returns
  /// Status::invalid_input; the scene stays usable.
  Status step() noexcept {
    std::array<Eigen::Isometry3d, ModelType::n_links> poses;
    for (std::size_t l = 0; l < ModelType::n_links; ++l) {
      poses[l] = link_pose(static_cast<int>(l));
      if (link_body_[l] >= 0 && !World<S>::target_in_range(poses[l])) return Status::invalid_input;
    }
    // The joints of each link's chain in world axes where the links are now (placed_).
    const Mat3 R = placed_.linear();
    std::array<BodyJoint, k_max_body_joints> chain;
    for (std::size_t l = 0; l < ModelType::n_links; ++l) {
      if (link_body_[l] < 0) continue;
      world_.set_target(link_body_[l], poses[l]);
      int n = 0;
      for (const SupportJoint& j : M.support(static_cast<int>(l))) {
        const auto u = static_cast<std::size_t>(j.link);
        BodyJoint& b = chain[static_cast<std::size_t>(n++)];
        b.actuator = actuator_[static_cast<std::size_t>(j.q)];
        b.axis = R * kin_.axis[u];
        b.origin = placed_ * kin_.p[u];
        b.gear = j.multiplier;
        b.prismatic = j.type == JointType::prismatic;
      }
      world_.set_body_joints(link_body_[l],
                             std::span<const BodyJoint>(chain.data(), static_cast<std::size_t>(n)));
    }
    update_joint_space();
    for (int i = 0; i < nq; ++i) {
      const int a = actuator_[static_cast<std::size_t>(i)];
      world_.set_actuator_inertia(a, inertia_[i]);
      world_.set_actuator_force(a, gravity_force_[i]);
    }
    const Status status = world_.step();
    if (status != Status::success) return status;
    for (int i = 0; i < nq; ++i)
      q_[i] = static_cast<double>(world_.actuator(actuator_[static_cast<std::size_t>(i)]).q);
    forward_kinematics(kin_, q_);
    placed_ = hand_pose_;
    for (std::size_t l = 0; l < ModelType::n_links; ++l)
      if (link_body_[l] >= 0) world_.move_kinematic(link_body_[l], link_pose(static_cast<int>(l)));
    return status;
  }

  /// The world pose of link \p l at the joints' positions and the current hand pose.
  [[nodiscard]] Eigen::Isometry3d link_pose(int l) const noexcept {
    return hand_pose_ * topograsp::link_pose(kin_, l);
  }

  /// The number of hand-object contact points with a separation of at most \p max_separation (m).
  [[nodiscard]] int hand_contacts(double max_separation = 0.0) const noexcept {
    int n = 0;
    for_each_contact(world_.manifolds(), object_,
                     [&](const Manifold<S>&, const ContactPoint<S>& p) {
                       if (static_cast<double>(p.separation) <= max_separation) ++n;
                     });
    return n;
  }
  /// The total normal force (N) of the hand on the object over the last step.
  [[nodiscard]] double hand_force() const noexcept {
    double sum = 0.0;
    for_each_contact(world_.manifolds(), object_,
                     [&](const Manifold<S>&, const ContactPoint<S>& p) {
                       sum += static_cast<double>(p.step_impulse);
                     });
    return sum / world_.options().time_step;
  }

  /// The deepest hand-object overlap at the last step (m, >= 0; 0 when nothing overlaps).
  [[nodiscard]] double deepest_penetration() const noexcept {
    double deepest = 0.0;
    for_each_contact(world_.manifolds(), object_,
                     [&](const Manifold<S>&, const ContactPoint<S>& p) {
                       deepest = std::max(deepest, -static_cast<double>(p.separation));
                     });
    return deepest;
  }
  /// Gravity in the world frame (m/s^2).
  [[nodiscard]] Vec3 gravity() const noexcept { return world_.gravity().template cast<double>(); }
  /// Sets gravity in the world frame (m/s^2); throws as World::set_gravity().
  void set_gravity(const Vec3& g) { world_.set_gravity(g); }
  /// The object's mass (kg).
  [[nodiscard]] double object_mass() const noexcept {
    return static_cast<double>(world_.body(object_).mass);
  }
  /// The object's centre of mass in the world (m).
  [[nodiscard]] Vec3 object_com() const noexcept {
    return world_.body(object_).x.template cast<double>();
  }
  /// The palm centre in the world (m): the model's palm point, or the hand frame's origin for a
  /// model without a hand.
  [[nodiscard]] Vec3 palm_centre() const noexcept {
    if constexpr (M.is_hand())
      return hand_pose_ * world_point(kin_, M.palm);
    else
      return hand_pose_.translation();
  }
  /// The time step (s).
  [[nodiscard]] double time_step() const noexcept { return world_.options().time_step; }

  /// The object frame in the world.
  [[nodiscard]] Eigen::Isometry3d object_pose() const noexcept {
    return world_.body(object_).pose();
  }
  /// The object frame in the hand frame.
  [[nodiscard]] Eigen::Isometry3d object_in_hand() const noexcept {
    return hand_pose_.inverse() * object_pose();
  }
  /// The hand frame pose the next step drives the hand to.
  [[nodiscard]] const Eigen::Isometry3d& hand_pose() const noexcept { return hand_pose_; }
  /// The motors' targets (dim nq).
  [[nodiscard]] const Config& joint_targets() const noexcept { return target_; }
  /// The World that holds the hand and the object.
  [[nodiscard]] const World<S>& world() const noexcept { return world_; }
  [[nodiscard]] World<S>& world() noexcept { return world_; }
  /// The object's body in world().
  [[nodiscard]] int object_body() const noexcept { return object_; }
  /// The World body of link \p l, or -1 if the link has no shapes.
  [[nodiscard]] int link_body(int l) const noexcept {
    return link_body_[static_cast<std::size_t>(l)];
  }
  /// The options the scene was built with.
  [[nodiscard]] const HandSceneOptions& options() const noexcept { return options_; }
  /// Forward kinematics at the joints' positions (hand frame).
  [[nodiscard]] const KinematicsData<M>& kinematics() const noexcept { return kin_; }

  /// What is wrong with \p pose as a hand pose ("" if nothing): not finite, not a rotation
  /// (orthonormal, det +1, to 1e-6), or a coordinate above k_max_hand_coordinate. The one check
  /// behind the constructor and set_hand_pose, for callers that report instead of throwing.
  [[nodiscard]] static std::string hand_pose_problem(const Eigen::Isometry3d& pose) {
    if (!pose.matrix().allFinite()) return "expected a finite number";
    const Mat3 R = pose.linear();
    if (!is_rotation(R)) return "expected a rotation (orthonormal, det +1)";
    const double m = pose.translation().cwiseAbs().maxCoeff();
    if (!(m <= k_max_hand_coordinate)) {
      char buf[96];
      static_assert(k_max_hand_coordinate == 1e6, "the message below says 1e6");
      std::snprintf(buf, sizeof buf, "expected coordinates of at most 1e6 m, got %.6g m", m);
      return buf;
    }
    return {};
  }

  /// The hand-object contact points of the last step with a separation of at most
  /// \p max_separation (m), each with the name of the link it is on, the world point,
  /// the unit normal pointing into the object and the normal force it carried over the last step
  /// (N, >= 0): what a record of the grasp keeps (CloseResult::contact_points). Allocates the
  /// returned vector.
  [[nodiscard]] std::vector<HandContact> hand_contact_list(double max_separation = 0.0) const {
    std::vector<HandContact> out;
    const double dt = world_.options().time_step;
    for_each_hand_contact(max_separation, [&](const Manifold<S>& m, const ContactPoint<S>& p,
                                              const Vec3& normal) {
      const int body = m.body_a == object_ ? m.body_b : m.body_a;
      const auto l = std::find(link_body_.begin(), link_body_.end(), body) - link_body_.begin();
      std::string link;
      if (l < static_cast<std::ptrdiff_t>(link_body_.size()))
        link = std::string(M.links[static_cast<std::size_t>(l)].spec.name.view());
      out.push_back({std::move(link), p.point.template cast<double>(), normal,
                     static_cast<double>(p.step_impulse) / dt, static_cast<double>(m.friction)});
    });
    return out;
  }

  /// The hand-object contact points of the last step with a separation of at most
  /// \p max_separation (m), as the Ferrari-Canny epsilon takes them (ferrari_canny_epsilon() in
  /// evaluation/grasp_quality.hpp): the world point, the unit normal pointing into the object and
  /// the pair's friction coefficient. Empty before the first step. Allocates the returned vector.
  [[nodiscard]] std::vector<ContactForQuality> hand_contact_points(
      double max_separation = 0.0) const {
    std::vector<ContactForQuality> out;
    for_each_hand_contact(
        max_separation, [&](const Manifold<S>& m, const ContactPoint<S>& p, const Vec3& normal) {
          out.push_back({p.point.template cast<double>(), normal, static_cast<double>(m.friction)});
        });
    return out;
  }

 private:
  // Calls f(manifold, point, unit normal into the object) for each hand-object contact point of
  // the last step with a separation of at most max_separation (m).
  template <class F>
  void for_each_hand_contact(double max_separation, F&& f) const {
    for_each_contact(world_.manifolds(), object_,
                     [&](const Manifold<S>& m, const ContactPoint<S>& p) {
                       if (!(static_cast<double>(p.separation) <= max_separation)) return;
                       // A manifold's normal points from body A into body B.
                       const double into_object = m.body_b == object_ ? 1.0 : -1.0;
                       f(m, p, Vec3(into_object * p.normal.template cast<double>()));
                     });
  }
  // Every actuated joint needs a motor: an effort and a velocity limit.
  static void require_motors() {
    for (int i = 0; i < nq; ++i) {
      const LinkSpec& s = M.joint_spec(i);
      if (!(M.joint_spec(i).effort > 0.0 && M.joint_spec(i).velocity > 0.0))
        detail::throw_invalid_argument(
            "model", "joint '" + std::string(s.name.view()) + "' of '" +
                         std::string(M.name.view()) +
                         "' has no motor: give it LinkSpec::actuator(effort, velocity, armature)");
    }
  }
  // The diagonal of the joint-space inertia at the joints' positions (kin_), plus the rotors',
  // and the generalised force of the links' weights; hand frame axes, so gravity is rotated in.
  void update_joint_space() noexcept {
    inertia_ = Config::Zero();
    gravity_force_ = Config::Zero();
    const Vec3 g = hand_pose_.linear().transpose() * world_.gravity().template cast<double>();
    for (int i = 0; i < nq; ++i) inertia_[i] = M.joint_spec(i).armature;
    for (std::size_t l = 0; l < ModelType::n_links; ++l) {
      const double m = M.links[l].spec.mass;
      if (!(m > 0.0)) continue;
      const Vec3 c = kin_.p[l] + kin_.R[l] * link_com_[l];
      const Mat3 I = kin_.R[l] * link_inertia_[l] * kin_.R[l].transpose();
      const Mat<3, nq> Jv = point_jacobian(kin_, static_cast<int>(l), c);
      const Mat<3, nq> Jw = link_rotation_jacobian(kin_, static_cast<int>(l));
      for (int i = 0; i < nq; ++i) {
        inertia_[i] += m * Jv.col(i).squaredNorm() + Jw.col(i).dot(I * Jw.col(i));
        gravity_force_[i] += m * g.dot(Jv.col(i));
      }
    }
    for (int i = 0; i < nq; ++i)
      if (!(inertia_[i] > 0.0)) inertia_[i] = k_min_inertia;
  }
  // An actuator that moves no mass and has no rotor inertia (a model without that data) gets
  // this inertia (kg m^2): a light finger joint's.
  static constexpr double k_min_inertia = 1e-5;

  static void require_hand_pose(const Eigen::Isometry3d& pose, std::string_view argument) {
    const std::string problem = hand_pose_problem(pose);
    if (!problem.empty()) detail::throw_invalid_argument(argument, problem);
  }

  World<S> world_;
  HandSceneOptions options_;
  KinematicsData<M> kin_;
  Eigen::Isometry3d hand_pose_ = Eigen::Isometry3d::Identity();  // target of the next step
  Eigen::Isometry3d placed_ = Eigen::Isometry3d::Identity();     // where the links are now
  Config q_ = Config::Zero();                                    // the joints' positions
  Config target_ = Config::Zero();                               // the motors' targets
  Config inertia_ = Config::Zero(), gravity_force_ = Config::Zero();
  double effort_fraction_ = 1.0;
  std::array<int, static_cast<std::size_t>(nq)> actuator_{};
  std::array<Vec3, ModelType::n_links> link_com_{};
  std::array<Mat3, ModelType::n_links> link_inertia_{};
  std::array<int, ModelType::n_links> link_body_{};
  int object_ = -1;
};

}  // namespace topograsp
