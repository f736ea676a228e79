// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// World: the rigid-body stepper. Bodies made of shapes, contacts between them, and a sub-stepped
/// soft-step solver with warm starting, circular friction cones and torsional friction.
#pragma once

#include <cmath>
#include <span>
#include <string>
#include <vector>

#include <topograsp/core/assert.hpp>
#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/core/status.hpp>
#include <topograsp/geometry/mass_properties.hpp>
#include <topograsp/geometry/primitive.hpp>
#include <topograsp/physics/actuator.hpp>
#include <topograsp/physics/body_contacts.hpp>
#include <topograsp/physics/collider.hpp>
#include <topograsp/physics/contact.hpp>
#include <topograsp/physics/contact_solver.hpp>
#include <topograsp/physics/detail/contact_slots.hpp>
#include <topograsp/physics/detail/step.hpp>
#include <topograsp/physics/detail/step_undo.hpp>
#include <topograsp/physics/detail/world_checks.hpp>
#include <topograsp/physics/polytope.hpp>
#include <topograsp/physics/rigid_body.hpp>
#include <topograsp/physics/stepper_options.hpp>

namespace topograsp {

/// The rigid-body stepper over the scalar type \p S (double; float compiles and runs).
///
/// Build a scene with add_body(); then call step() at the fixed time step. Once built, step()
/// allocates nothing: every contact slot (one per pair of shapes that can touch) exists from
/// add_body() on. One step:
///  1. kinematic bodies with a target get the velocity that reaches it in one step (ramped
///     linearly through the step from the previous step's, see detail::kinematic_substep());
///  2. the narrow phase finds up to 4 contacts per pair of shapes (including speculative ones
///     closer than StepperOptions::speculative_distance) and matches them by feature id to the
///     previous step's, to warm start them;
///  3. for each of StepperOptions::substeps sub-steps of h = dt / substeps: integrate velocities
///     (gravity), warm start, solve contacts with a soft position bias, integrate positions
///     (semi-implicit Euler; rotations by the exact exponential), relax contacts without bias
///     (the "soft step" of Box2D v3; the contact stages are the free functions of
///     physics/contact_solver.hpp, which step() calls in this order);
///  4. kinematic bodies are placed exactly at their targets; a non-finite state, a speed above
///     StepperOptions::max_speed or a position beyond max_length() of any dynamic body undoes the
///     step and ends the run with Status::numerical_issue, in the step where it happens.
///
/// Ranges: what add_body(), set_pose(), set_target(), set_velocity() and the options accept is
/// what S represents with margin (sizes and coordinates within [min_length(), max_length()],
/// masses and inertias whose kinetic energy at max_speed stays finite, a time step short enough
/// for the speculative contacts); anything else is refused with topograsp::invalid_argument, so
/// an accepted scene never turns a derived quantity (inertia, kinetic energy) into inf or NaN.
///
/// Limits: no restitution, no joints between dynamic bodies, no gyroscopic torque (bodies spin
/// about a fixed axis in the absence of contacts), no sleeping, no broad phase beyond
/// bounding-sphere tests of the precomputed shape pairs (fine for tens of shapes).
template <class S = double>
class World {
 public:
  using V3 = Vec<3, S>;
  using M3 = Mat<3, 3, S>;

  /// The largest magnitude (m) of a shape size, a coordinate of a pose, a body position, and of
  /// StepperOptions::max_speed (m/s): sqrt(largest S) / 1024, 1.3e151 for double and 1.8e16 for
  /// float, so that squared distances and speeds (and sums of a few of them) stay finite in S.
  [[nodiscard]] static S max_length() noexcept { return detail::max_length<S>(); }
  /// The smallest shape size (m): sqrt(smallest normal S) * 1024, 1.5e-151 for double and 1.1e-16
  /// for float, so that squared sizes stay normal numbers in S.
  [[nodiscard]] static S min_length() noexcept { return detail::min_length<S>(); }

  /// An empty world. Throws topograsp::invalid_argument naming the option if one is out of range:
  /// a non-positive time step, one the scalar type cannot hold (1e291 s is inf in float), or one
  /// whose sub-step (time_step / substeps, in S) is below min_length() (1e-203 s is 0 in float: the
  /// step divided by it), fewer than 1 or more than 1000
  /// sub-steps, a negative stiffness, a non-finite value, a max_speed above max_length(), or a time
  /// step too long for the speculative contacts to catch a body under gravity: |gravity| *
  /// time_step^2 must not exceed speculative_distance (a body released at rest moves g dt^2 in its
  /// first step, semi-implicit Euler; a longer step lets it pass into or through a surface before
  /// any contact exists: with dt = 1 s a box falls 9.8 m in one step, through a 1 m thick ground).
  /// The defaults give 9.81 / 60^2 = 2.7 mm <= 5 mm.
  explicit World(const StepperOptions& options = {}) : options_(options) {
    detail::require_stepper_options<S>(options);
    gravity_ = Eigen::Vector3d(options.gravity[0], options.gravity[1], options.gravity[2])
                   .template cast<S>();
  }

  /// Adds a body and returns its index. Allocates (the body, its shapes and the contact slots of
  /// every pair it can form). Throws topograsp::invalid_argument naming the argument for no
  /// shapes, a non-positive or non-finite size, mass, density or friction, or a non-finite pose;
  /// and for what S cannot represent: a shape size outside [min_length(), max_length()], a pose
  /// coordinate (of the body or of a shape) above max_length(), friction above 1e6, and for a
  /// dynamic body a mass or inertia (given, or derived from the density) that is not a normal
  /// positive number of S with a finite inverse, or whose kinetic energy at
  /// StepperOptions::max_speed would overflow (mass * max_speed^2, inertia * max_speed^2); and
  /// for a given BodyDesc::inertial that is not physical ("desc.inertial.mass", ".com",
  /// ".inertia": a non-positive mass, a non-finite centre, an inertia not symmetric, not positive
  /// definite or breaking the triangle inequality).
  int add_body(const BodyDesc& desc) {
    detail::require_body_desc<S>(desc);
    RigidBody<S> b;
    b.type = desc.type;
    b.friction = static_cast<S>(desc.friction);
    const M3 R0 = detail::rotation_of<S>(desc.pose);
    const V3 p0 = detail::translation_of<S>(desc.pose);
    b.q = detail::Quat<S>(R0).normalized();
    b.R = b.q.toRotationMatrix();
    if (desc.type == BodyType::dynamic) {
      const MassProperties<S> mp =
          desc.inertial
              ? MassProperties<S>{static_cast<S>(desc.inertial->mass),
                                  desc.inertial->com.template cast<S>(),
                                  desc.inertial->inertia.template cast<S>()}
              : body_mass_properties<S>(desc.shapes, desc.mass, desc.density, desc.shape_density);
      b.mass = mp.mass;
      b.inv_mass = S(1) / mp.mass;
      b.local_com = mp.com;
      b.inertia = mp.inertia;
      b.inv_inertia_local = detail::inverse_in_range<S>(mp.inertia);
      b.update_world_inertia();
      detail::require_representable_mass(b, options_,
                                         desc.inertial                ? "desc.inertial"
                                         : desc.mass > 0.0            ? "desc.mass"
                                         : desc.shape_density.empty() ? "desc.density"
                                                                      : "desc.shape_density");
    }
    b.x = p0 + b.R * b.local_com;
    b.first_collider = static_cast<int>(colliders_.size());
    b.n_colliders = static_cast<int>(desc.shapes.size());
    const int index = static_cast<int>(bodies_.size());
    for (const ShapeSpec& s : desc.shapes)
      colliders_.push_back(detail::make_collider<S>(s, index, b.local_com, polytopes_));
    bodies_.push_back(b);
    targets_.push_back(detail::KinematicTarget<S>{b.R, b.x, false});
    joints_.push_back({});
    saved_.push_back({});
    turned_.push_back(M3::Identity());
    update_colliders(index);
    detail::add_contact_slots<S>(manifolds_, bodies_, index);
    return index;
  }

  /// Sets the Coulomb friction coefficient of the contact slot between shapes \p collider_a and
  /// \p collider_b (either order; collider indices, see collider()) to \p mu, in place of the
  /// sqrt(mu_a mu_b) of their bodies that add_body() gave it: friction per pair of materials.
  /// Other pairs keep theirs. Allocates nothing. Throws topograsp::invalid_argument naming
  /// "collider_a" or "collider_b" for an index out of range, "collider_b" for two shapes with no
  /// contact slot (the same body, or two bodies neither of which is dynamic), and "mu" for a value
  /// that is negative, not finite or above 1e6.
  void set_pair_friction(int collider_a, int collider_b, double mu) {
    detail::require_index(collider_a, colliders_.size(), "collider", "collider_a");
    detail::require_index(collider_b, colliders_.size(), "collider", "collider_b");
    require_non_negative(mu, "mu");
    if (mu > 1e6)
      detail::throw_invalid_argument("mu", "expected at most 1e6, got " + detail::number(mu));
    for (Manifold<S>& m : manifolds_)
      if ((m.collider_a == collider_a && m.collider_b == collider_b) ||
          (m.collider_a == collider_b && m.collider_b == collider_a)) {
        m.friction = static_cast<S>(mu);
        return;
      }
    detail::throw_invalid_argument(
        "collider_b", "shapes " + std::to_string(collider_a) + " and " +
                          std::to_string(collider_b) +
                          " have no contact slot (the same body, or no dynamic body between them)");
  }

  /// Sets the pose that kinematic body \p body reaches at the end of the next step (its body
  /// frame in the world); the step gives it the constant velocity that gets it there.
  /// Throws topograsp::invalid_argument for a bad index, a non-kinematic body, a non-finite pose
  /// or a coordinate above max_length() (target_in_range() tells without throwing).
  void set_target(int body, const Eigen::Isometry3d& pose) {
    require_kinematic(body);
    detail::require_world_pose<S>(pose, "pose");
    detail::KinematicTarget<S>& t = targets_[static_cast<std::size_t>(body)];
    t.R = orthonormalized(pose.linear().template cast<S>());
    t.p = pose.translation().template cast<S>();
    t.active = true;
  }

  /// True if \p pose is finite with every coordinate at most max_length(): what set_target() and
  /// set_pose() accept as a pose.
  [[nodiscard]] static bool target_in_range(const Eigen::Isometry3d& pose) noexcept {
    return pose.matrix().allFinite() &&
           pose.translation().cwiseAbs().maxCoeff() <= static_cast<double>(max_length());
  }

  /// Moves body \p body to \p pose (its body frame in the world) at once, without velocity.
  /// Throws topograsp::invalid_argument for a bad index, a non-finite pose or a coordinate above
  /// max_length().
  void set_pose(int body, const Eigen::Isometry3d& pose) {
    detail::require_index(body, bodies_.size(), "body", "body");
    detail::require_world_pose<S>(pose, "pose");
    RigidBody<S>& b = bodies_[static_cast<std::size_t>(body)];
    b.R = orthonormalized(pose.linear().template cast<S>());
    b.q = detail::Quat<S>(b.R).normalized();
    b.R = b.q.toRotationMatrix();
    b.x = pose.translation().template cast<S>() + b.R * b.local_com;
    b.update_world_inertia();
    targets_[static_cast<std::size_t>(body)] = detail::KinematicTarget<S>{b.R, b.x, false};
    update_colliders(body);
  }

  /// Sets the velocity of body \p body: \p v of its centre of mass (m/s) and \p w (rad/s), both
  /// in the world frame. Ignored for fixed bodies. Throws topograsp::invalid_argument for a bad
  /// index, non-finite values, or a speed |v| or |w| above StepperOptions::max_speed (which would
  /// end the run at the next step).
  void set_velocity(int body, const Eigen::Vector3d& v, const Eigen::Vector3d& w) {
    detail::require_index(body, bodies_.size(), "body", "body");
    detail::require_velocity(v, w, options_);
    RigidBody<S>& b = bodies_[static_cast<std::size_t>(body)];
    if (b.type == BodyType::fixed) return;
    b.v = v.template cast<S>();
    b.w = w.template cast<S>();
  }

  /// Holds dynamic body \p body still (\p held true), as a fixture holds an object while a hand
  /// closes on it: it stays where it is, at rest, and keeps its contacts, but with an infinite
  /// mass and inertia, so that nothing moves it and whatever presses on it stalls there. False
  /// releases it, at rest, with its own mass and inertia again. Throws
  /// topograsp::invalid_argument for a bad index or a body that is not dynamic.
  void set_held(int body, bool held) {
    detail::require_index(body, bodies_.size(), "body", "body");
    RigidBody<S>& b = bodies_[static_cast<std::size_t>(body)];
    if (b.type != BodyType::dynamic)
      detail::throw_invalid_argument("body", "expected a dynamic body");
    b.held = held;
    b.v.setZero();
    b.w.setZero();
    b.inv_mass = held ? S(0) : S(1) / b.mass;
    b.inv_inertia_local = held ? M3::Zero() : M3(detail::inverse_in_range<S>(b.inertia));
    b.update_world_inertia();
  }
  /// True while body \p body is held (set_held()).
  [[nodiscard]] bool held(int body) const noexcept {
    return bodies_[static_cast<std::size_t>(body)].held;
  }

  /// Adds a joint-space actuator (see ActuatorDesc) and returns its index. Allocates. Throws
  /// topograsp::invalid_argument naming the field ("desc.inertia", ...) for a non-finite value,
  /// lower above upper, a position outside [lower, upper], or an inertia, max_effort,
  /// max_velocity or stiffness that is not positive, a negative damping_time; and for values S
  /// cannot hold (limits and
  /// position beyond max_length(), an inertia outside [min_length(), max_length()], a
  /// max_velocity above StepperOptions::max_speed).
  int add_actuator(const ActuatorDesc& desc) {
    detail::require_actuator_desc<S>(desc, options_);
    detail::Actuator<S> a;
    a.q = a.q0 = a.target = static_cast<S>(desc.position);
    a.lower = static_cast<S>(desc.lower);
    a.upper = static_cast<S>(desc.upper);
    a.inertia = static_cast<S>(desc.inertia);
    a.inv_inertia = S(1) / a.inertia;
    a.max_effort = static_cast<S>(desc.max_effort);
    a.max_velocity = static_cast<S>(desc.max_velocity);
    a.stiffness = static_cast<S>(desc.stiffness);
    a.damping = static_cast<S>(desc.stiffness * desc.damping_time);
    actuators_.push_back(a);
    saved_actuators_.push_back({});
    return static_cast<int>(actuators_.size()) - 1;
  }
  /// The number of actuators.
  [[nodiscard]] int actuator_count() const noexcept { return static_cast<int>(actuators_.size()); }
  /// The state of actuator \p a (position q, velocity qd, target, limits, ...).
  [[nodiscard]] const detail::Actuator<S>& actuator(int a) const noexcept {
    TOPOGRASP_ASSERT(a >= 0 && a < actuator_count(), "actuator index out of range");
    return actuators_[static_cast<std::size_t>(a)];
  }
  /// The torque (N m, or force N) the servo of actuator \p a gave over the last step (mean).
  [[nodiscard]] double actuator_torque(int a) const noexcept {
    return static_cast<double>(actuator(a).step_impulse) / options_.time_step;
  }
  /// Sets the servo target of actuator \p a (rad or m; a target beyond a limit drives the joint
  /// to the limit). Throws topograsp::invalid_argument for a bad index or a value that is not
  /// finite or beyond max_length().
  void set_actuator_target(int a, double target) {
    detail::require_index(a, actuators_.size(), "actuator", "a");
    require_finite(target, "target");
    if (!(std::abs(target) <= static_cast<double>(max_length())))
      detail::throw_invalid_argument("target", "expected at most " + detail::number(max_length()));
    actuators_[static_cast<std::size_t>(a)].target = static_cast<S>(target);
  }
  /// Sets the torque limit of actuator \p a's servo (N m or N, > 0). Throws
  /// topograsp::invalid_argument for a bad index or a value that is not positive and finite.
  void set_actuator_max_effort(int a, double max_effort) {
    detail::require_index(a, actuators_.size(), "actuator", "a");
    require_positive(max_effort, "max_effort");
    actuators_[static_cast<std::size_t>(a)].max_effort = static_cast<S>(max_effort);
  }
  /// Sets the servo gains of actuator \p a: its \p stiffness (N m/rad or N/m, > 0) and its
  /// damping, stiffness * \p damping_time (s, >= 0), as ActuatorDesc gives them. Throws
  /// topograsp::invalid_argument for a bad index or a value outside those ranges.
  void set_actuator_gains(int a, double stiffness, double damping_time) {
    detail::require_index(a, actuators_.size(), "actuator", "a");
    require_positive(stiffness, "stiffness");
    require_non_negative(damping_time, "damping_time");
    detail::Actuator<S>& x = actuators_[static_cast<std::size_t>(a)];
    x.stiffness = static_cast<S>(stiffness);
    x.damping = static_cast<S>(stiffness * damping_time);
  }
  /// Sets the inertia of actuator \p a (kg m^2 or kg), e.g. each step from the configuration.
  /// Throws topograsp::invalid_argument as ActuatorDesc::inertia is checked.
  void set_actuator_inertia(int a, double inertia) {
    detail::require_index(a, actuators_.size(), "actuator", "a");
    detail::require_actuator_inertia<S>(inertia, "inertia");
    detail::Actuator<S>& x = actuators_[static_cast<std::size_t>(a)];
    x.inertia = static_cast<S>(inertia);
    x.inv_inertia = S(1) / x.inertia;
  }
  /// Sets the external generalised force on actuator \p a for the next steps (N m or N; e.g.
  /// the weight of the links it carries). Throws topograsp::invalid_argument for a bad index or
  /// a non-finite value.
  void set_actuator_force(int a, double force) {
    detail::require_index(a, actuators_.size(), "actuator", "a");
    require_finite(force, "force");
    actuators_[static_cast<std::size_t>(a)].force = static_cast<S>(force);
  }
  /// Puts actuator \p a at \p position at once, at rest, with its target there and its
  /// accumulated impulses cleared. Throws topograsp::invalid_argument for a bad index or a
  /// position outside its limits.
  void set_actuator_position(int a, double position) {
    detail::require_index(a, actuators_.size(), "actuator", "a");
    detail::Actuator<S>& x = actuators_[static_cast<std::size_t>(a)];
    require_finite(position, "position");
    if (position < static_cast<double>(x.lower) || position > static_cast<double>(x.upper))
      detail::throw_invalid_argument("position", "expected a value in [" + detail::number(x.lower) +
                                                     ", " + detail::number(x.upper) + "], got " +
                                                     detail::number(position));
    x.q = x.q0 = x.target = static_cast<S>(position);
    x.qd = x.motor_impulse = x.lower_impulse = x.upper_impulse = x.step_impulse = S(0);
  }
  /// Declares the joints that carry kinematic body \p body for the next step (its chain, e.g. a
  /// finger link's joints in world axes at the step's start): contacts on the body then push on
  /// those actuators, and the body's contact points move with them within the step. The caller
  /// moves the body to where the actuators took it after the step (move_kinematic()). An empty
  /// span detaches the body. Allocates nothing. Throws topograsp::invalid_argument naming the
  /// argument for a bad body index or a body that is not kinematic, more than k_max_body_joints
  /// joints, a bad actuator index, a non-unit or non-finite axis, a non-finite origin or gear.
  void set_body_joints(int body, std::span<const BodyJoint> joints) {
    require_kinematic(body);
    detail::require_body_joints<S>(joints, actuators_.size());
    detail::BodyJoints<S>& out = joints_[static_cast<std::size_t>(body)];
    out.count = static_cast<int>(joints.size());
    for (std::size_t j = 0; j < joints.size(); ++j) {
      out.actuator[j] = joints[j].actuator;
      out.axis[j] = joints[j].axis.template cast<S>();
      out.origin[j] = joints[j].origin.template cast<S>();
      out.gear[j] = static_cast<S>(joints[j].gear);
      out.prismatic[j] = joints[j].prismatic;
    }
  }
  /// Moves kinematic body \p body to \p pose at once, keeping its motion across steps (the
  /// velocity ramp of detail::kinematic_substep()): for a body carried by actuators, placed after
  /// each step where they took it. Throws as set_pose() does, and for a body that is not kinematic.
  void move_kinematic(int body, const Eigen::Isometry3d& pose) {
    require_kinematic(body);
    detail::require_world_pose<S>(pose, "pose");
    RigidBody<S>& b = bodies_[static_cast<std::size_t>(body)];
    b.R = orthonormalized(pose.linear().template cast<S>());
    b.q = detail::Quat<S>(b.R).normalized();
    b.R = b.q.toRotationMatrix();
    b.x = pose.translation().template cast<S>() + b.R * b.local_com;
    update_colliders(body);
  }

  /// Sets gravity (m/s^2, world frame). Throws topograsp::invalid_argument naming "g" for
  /// non-finite values or when |g| * time_step^2 exceeds StepperOptions::speculative_distance
  /// (see the constructor).
  void set_gravity(const Eigen::Vector3d& g) {
    require_finite(g, "g");
    detail::require_step_catches_fall(g, options_, "g");
    gravity_ = g.template cast<S>();
  }
  /// Gravity (m/s^2, world frame).
  [[nodiscard]] V3 gravity() const noexcept { return gravity_; }

  /// Advances the world by one time step (see the class comment). Allocates nothing. Returns
  /// Status::success, or Status::numerical_issue when the state became non-finite, too fast or too
  /// far (beyond max_length()); then
  /// the step is undone (the bodies and actuators as before it, its contacts discarded: every
  /// manifold empty, so every number stays finite) and later calls do nothing and return it again.
  Status step() noexcept {
    if (status_ != Status::success) return status_;
    const detail::StepContext<S> ctx =
        detail::make_step_context<S>(bodies_, joints_, actuators_, turned_, options_, gravity_);
    detail::save_state<S>(bodies_, actuators_, saved_, saved_actuators_);
    detail::begin_actuator_step(ctx);
    detail::drive_kinematic<S>(ctx, targets_);
    detail::find_contacts<S>(manifolds_, colliders_, polytopes_,
                             static_cast<S>(options_.speculative_distance));
    detail::prepare_contacts<S>(manifolds_, ctx);
    for (int sub = 0; sub < ctx.substeps; ++sub) {
      detail::kinematic_substep<S>(ctx, targets_, sub);
      detail::integrate_velocities(ctx);
      detail::warm_start_actuators<S>(actuators_);
      detail::warm_start_contacts<S>(manifolds_, ctx);
      update_turned();
      for (int it = 0; it < options_.iterations; ++it) {
        detail::solve_actuators<S>(actuators_, ctx.h, detail::SolvePass::biased, ctx.push);
        detail::solve_contacts<S>(manifolds_, ctx, detail::SolvePass::biased);
      }
      detail::integrate_positions(ctx);
      update_turned();
      for (int it = 0; it < options_.iterations; ++it) {
        detail::solve_actuators<S>(actuators_, ctx.h, detail::SolvePass::relax, ctx.push);
        detail::solve_contacts<S>(manifolds_, ctx, detail::SolvePass::relax);
      }
      detail::accumulate_impulses<S>(manifolds_);
      detail::end_actuator_substep(ctx);
    }
    detail::finish_kinematic<S>(ctx, targets_);
    for (int i = 0; i < static_cast<int>(bodies_.size()); ++i) update_colliders(i);
    detail::store_impulses<S>(manifolds_);
    if (!detail::state_ok<S>(bodies_, actuators_, static_cast<S>(options_.max_speed),
                             max_length())) {
      detail::restore_state<S>(bodies_, actuators_, saved_, saved_actuators_, colliders_);
      // The undone step's contacts are discarded: their impulses may be what went non-finite.
      for (Manifold<S>& m : manifolds_) m.count = 0;
      status_ = Status::numerical_issue;
      return status_;
    }
    time_ += options_.time_step;
    ++steps_;
    return status_;
  }

  /// The body \p i.
  [[nodiscard]] const RigidBody<S>& body(int i) const noexcept {
    TOPOGRASP_ASSERT(i >= 0 && i < body_count(), "body index out of range");
    return bodies_[static_cast<std::size_t>(i)];
  }
  /// The number of bodies.
  [[nodiscard]] int body_count() const noexcept { return static_cast<int>(bodies_.size()); }
  /// Every contact slot; those with count > 0 touched (or nearly) in the last step.
  [[nodiscard]] std::span<const Manifold<S>> manifolds() const noexcept { return manifolds_; }
  /// The shape \p i.
  [[nodiscard]] const Collider<S>& collider(int i) const noexcept {
    TOPOGRASP_ASSERT(i >= 0 && i < collider_count(), "collider index out of range");
    return colliders_[static_cast<std::size_t>(i)];
  }
  /// The number of shapes.
  [[nodiscard]] int collider_count() const noexcept { return static_cast<int>(colliders_.size()); }

  /// The number of contact points between bodies \p a and \p b (either order) at the last step
  /// whose separation was at most \p max_separation (m).
  [[nodiscard]] int contact_count(int a, int b, S max_separation = S(0)) const noexcept {
    int n = 0;
    for_each_contact(manifolds(), a, [&](const Manifold<S>& m, const ContactPoint<S>& p) {
      if (other_body(m, a) == b && p.separation <= max_separation) ++n;
    });
    return n;
  }

  /// The total normal impulse (N s) between bodies \p a and \p b over the last step.
  [[nodiscard]] S normal_impulse(int a, int b) const noexcept {
    S sum = S(0);
    for_each_contact(manifolds(), a, [&](const Manifold<S>& m, const ContactPoint<S>& p) {
      if (other_body(m, a) == b) sum += p.step_impulse;
    });
    return sum;
  }

  /// The options the world was built with.
  [[nodiscard]] const StepperOptions& options() const noexcept { return options_; }
  /// Status::success, or the status of the step that ended the run.
  [[nodiscard]] Status status() const noexcept { return status_; }
  /// Simulated time (s) and steps taken since construction.
  [[nodiscard]] double time() const noexcept { return time_; }
  [[nodiscard]] long steps() const noexcept { return steps_; }
  /// The total kinetic energy of the dynamic bodies (J).
  [[nodiscard]] S kinetic_energy() const noexcept {
    S e = S(0);
    for (const RigidBody<S>& b : bodies_) e += b.kinetic_energy();
    return e;
  }

  /// The shape \p i as the narrow phase sees it, at its current pose.
  [[nodiscard]] ShapeView<S> shape_view(int i) const noexcept {
    TOPOGRASP_ASSERT(i >= 0 && i < collider_count(), "collider index out of range");
    return detail::shape_view<S>(colliders_[static_cast<std::size_t>(i)], polytopes_);
  }

 private:
  void require_kinematic(int body) const {
    detail::require_index(body, bodies_.size(), "body", "body");
    if (bodies_[static_cast<std::size_t>(body)].type != BodyType::kinematic)
      detail::throw_invalid_argument("body", "expected a kinematic body");
  }
  static M3 orthonormalized(const M3& R) noexcept {
    return detail::Quat<S>(R).normalized().toRotationMatrix();
  }

  void update_colliders(int i) noexcept {
    detail::place_colliders<S>(bodies_[static_cast<std::size_t>(i)], colliders_);
  }

  // How far each body has turned since the step began (the contact solver's frame rotation).
  void update_turned() noexcept {
    TOPOGRASP_ASSERT(turned_.size() == bodies_.size() && saved_.size() == bodies_.size(),
                     "one scratch rotation and one saved state per body");
    for (std::size_t i = 0; i < bodies_.size(); ++i)
      turned_[i] = bodies_[i].type == BodyType::fixed ? M3::Identity()
                                                      : M3(bodies_[i].R * saved_[i].R.transpose());
  }

  StepperOptions options_;
  V3 gravity_ = V3::Zero();
  std::vector<RigidBody<S>> bodies_;
  std::vector<detail::KinematicTarget<S>> targets_;
  std::vector<detail::SavedBody<S>> saved_;
  std::vector<M3> turned_;  // rotation of each body since the step began (solver scratch)
  std::vector<Collider<S>> colliders_;
  std::vector<Polytope<S>> polytopes_;
  std::vector<Manifold<S>> manifolds_;
  std::vector<detail::BodyJoints<S>> joints_;  // one per body; count 0 unless actuators carry it
  std::vector<detail::Actuator<S>> actuators_;
  std::vector<detail::Actuator<S>> saved_actuators_;
  Status status_ = Status::success;
  double time_ = 0.0;
  long steps_ = 0;
};

}  // namespace topograsp
