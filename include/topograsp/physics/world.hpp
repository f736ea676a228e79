// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// World: the rigid-body stepper. Bodies made of shapes, contacts between them, and a sub-stepped
/// soft-step solver with warm starting, circular friction cones and torsional friction.
#pragma once

#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include <Eigen/Eigenvalues>

#include <topograsp/core/assert.hpp>
#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/core/status.hpp>
#include <topograsp/physics/actuator.hpp>
#include <topograsp/physics/contact.hpp>
#include <topograsp/physics/contact_solver.hpp>
#include <topograsp/physics/mass_properties.hpp>
#include <topograsp/physics/narrow_phase.hpp>
#include <topograsp/physics/polytope.hpp>
#include <topograsp/physics/rigid_body.hpp>
#include <topograsp/physics/stepper_options.hpp>

namespace topograsp {

/// A shape attached to a body of a World.
template <class S = double>
struct Collider {
  int body = -1;
  ShapeType type = ShapeType::sphere;
  detail::V3<S> size = detail::V3<S>::Zero();         ///< as ShapeSpec::size
  detail::M3<S> local_R = detail::M3<S>::Identity();  ///< in body axes
  detail::V3<S> local_p = detail::V3<S>::Zero();      ///< from the centre of mass
  S bounding_radius = S(0);  ///< of a sphere about the shape's centre that contains it (m)
  int polytope = -1;         ///< index into World's polytopes (boxes and cylinders)
  detail::M3<S> R = detail::M3<S>::Identity();  ///< world rotation (current)
  detail::V3<S> p = detail::V3<S>::Zero();      ///< world position (current)
  ShapeSpec spec{};                             ///< the shape as given, in the body frame
};

/// The rigid-body stepper over the scalar type \p S (double; float compiles and runs).
///
/// Build a scene with add_body(); then call step() at the fixed time step. Once built, step()
/// allocates nothing: every contact slot (one per pair of shapes that can touch) exists from
/// add_body() on. One step:
///  1. kinematic bodies with a target get the velocity that reaches it in one step (ramped
///     linearly through the step from the previous step's, see kinematic_substep());
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
  using V3 = detail::V3<S>;
  using M3 = detail::M3<S>;

  /// The largest magnitude (m) of a shape size, a coordinate of a pose, a body position, and of
  /// StepperOptions::max_speed (m/s): sqrt(largest S) / 1024, 1.3e151 for double and 1.8e16 for
  /// float, so that squared distances and speeds (and sums of a few of them) stay finite in S.
  [[nodiscard]] static S max_length() noexcept {
    return std::sqrt(std::numeric_limits<S>::max()) / S(1024);
  }
  /// The smallest shape size (m): sqrt(smallest normal S) * 1024, 1.5e-151 for double and 1.1e-16
  /// for float, so that squared sizes stay normal numbers in S.
  [[nodiscard]] static S min_length() noexcept {
    return std::sqrt(std::numeric_limits<S>::min()) * S(1024);
  }

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
    require_positive(options.time_step, "options.time_step");
    if (options.iterations < 1 || options.iterations > 100)
      detail::throw_invalid_argument(
          "options.iterations", "expected 1 to 100, got " + std::to_string(options.iterations));
    if (options.substeps < 1 || options.substeps > 1000)
      detail::throw_invalid_argument("options.substeps",
                                     "expected 1 to 1000, got " + std::to_string(options.substeps));
    if (!std::isfinite(static_cast<S>(options.time_step)))
      detail::throw_invalid_argument(
          "options.time_step",
          "expected a step the scalar type can hold, got " + number(options.time_step) + " s");
    if (!(static_cast<S>(options.time_step) / static_cast<S>(options.substeps) >= min_length()))
      detail::throw_invalid_argument(
          "options.time_step",
          "a sub-step (time_step / substeps) of " + number(options.time_step / options.substeps) +
              " s is below what the scalar type divides by safely (" + number(min_length()) + ")");
    for (std::size_t k = 0; k < 3; ++k) require_finite(options.gravity[k], "options.gravity");
    require_positive(options.contact_hertz, "options.contact_hertz");
    require_non_negative(options.contact_damping_ratio, "options.contact_damping_ratio");
    require_positive(options.contact_push_max_speed, "options.contact_push_max_speed");
    require_non_negative(options.hand_stiffness, "options.hand_stiffness");
    require_non_negative(options.hand_damping_ratio, "options.hand_damping_ratio");
    require_positive(options.hand_push_max_speed, "options.hand_push_max_speed");
    require_non_negative(options.torsional_friction_radius, "options.torsional_friction_radius");
    require_non_negative(options.speculative_distance, "options.speculative_distance");
    require_positive(options.max_speed, "options.max_speed");
    if (!(static_cast<S>(options.max_speed) <= max_length()))
      detail::throw_invalid_argument("options.max_speed",
                                     "expected at most " + number(max_length()) +
                                         " m/s (its square must stay finite), got " +
                                         number(options.max_speed));
    require_non_negative(options.linear_damping, "options.linear_damping");
    require_non_negative(options.angular_damping, "options.angular_damping");
    const Eigen::Vector3d g(options.gravity[0], options.gravity[1], options.gravity[2]);
    require_step_catches_fall(g, "options.time_step");
    gravity_ = g.template cast<S>();
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
    if (desc.shapes.empty())
      detail::throw_invalid_argument("desc.shapes", "expected at least one shape");
    for (std::size_t i = 0; i < desc.shapes.size(); ++i) {
      const std::string name = "desc.shapes[" + std::to_string(i) + "]";
      require_valid_shape(desc.shapes[i], name);
      require_representable_shape(desc.shapes[i], name);
    }
    require_pose(desc.pose, "desc.pose");
    require_coordinates(desc.pose.p, "desc.pose");
    require_non_negative(desc.friction, "desc.friction");
    if (desc.friction > 1e6)
      detail::throw_invalid_argument("desc.friction",
                                     "expected at most 1e6, got " + number(desc.friction));
    RigidBody<S> b;
    b.type = desc.type;
    b.friction = static_cast<S>(desc.friction);
    const M3 R0 = detail::rotation_of<S>(desc.pose);
    const V3 p0 = detail::translation_of<S>(desc.pose);
    b.q = detail::Quat<S>(R0).normalized();
    b.R = b.q.toRotationMatrix();
    if (!desc.shape_density.empty()) {
      if (desc.shape_density.size() != desc.shapes.size())
        detail::throw_invalid_argument("desc.shape_density",
                                       "expected one density per shape (" +
                                           std::to_string(desc.shapes.size()) + "), got " +
                                           std::to_string(desc.shape_density.size()));
      for (std::size_t i = 0; i < desc.shape_density.size(); ++i)
        require_positive(desc.shape_density[i], "desc.shape_density[" + std::to_string(i) + "]");
    }
    if (desc.type == BodyType::dynamic) {
      if (desc.inertial) require_physical_inertial(*desc.inertial, "desc.inertial");
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
      b.inv_inertia_local = inverse_in_range(mp.inertia);
      b.inv_inertia = b.R * b.inv_inertia_local * b.R.transpose();
      require_representable_mass(b, desc.inertial                ? "desc.inertial"
                                    : desc.mass > 0.0            ? "desc.mass"
                                    : desc.shape_density.empty() ? "desc.density"
                                                                 : "desc.shape_density");
    }
    b.x = p0 + b.R * b.local_com;
    b.first_collider = static_cast<int>(colliders_.size());
    b.n_colliders = static_cast<int>(desc.shapes.size());
    const int index = static_cast<int>(bodies_.size());
    for (const ShapeSpec& s : desc.shapes) {
      Collider<S> c;
      c.body = index;
      c.spec = s;
      c.type = s.type;
      c.size = V3(static_cast<S>(s.size[0]), static_cast<S>(s.size[1]), static_cast<S>(s.size[2]));
      c.local_R = detail::rotation_of<S>(s.pose);
      c.local_p = detail::translation_of<S>(s.pose) - b.local_com;
      switch (s.type) {
        case ShapeType::sphere:
          c.bounding_radius = c.size[0];
          break;
        case ShapeType::capsule:
          c.bounding_radius = c.size[0] + c.size[1];
          break;
        case ShapeType::box:
          c.bounding_radius = c.size.norm();
          c.polytope = static_cast<int>(polytopes_.size());
          polytopes_.push_back(box_polytope<S>(c.size));
          break;
        case ShapeType::cylinder:
          c.bounding_radius = std::sqrt(c.size[0] * c.size[0] + c.size[1] * c.size[1]);
          c.polytope = static_cast<int>(polytopes_.size());
          polytopes_.push_back(cylinder_polytope<S>(c.size[0], c.size[1]));
          break;
      }
      colliders_.push_back(c);
    }
    bodies_.push_back(b);
    targets_.push_back(Target{b.R, b.x, false});
    joints_.push_back({});
    saved_.push_back({});
    turned_.push_back(M3::Identity());
    update_colliders(index);
    // Contact slots with every earlier body that this one can touch.
    for (int j = 0; j < index; ++j) {
      const RigidBody<S>& o = bodies_[static_cast<std::size_t>(j)];
      if (o.type != BodyType::dynamic && b.type != BodyType::dynamic) continue;
      for (int ca = o.first_collider; ca < o.first_collider + o.n_colliders; ++ca)
        for (int cb = b.first_collider; cb < b.first_collider + b.n_colliders; ++cb) {
          Manifold<S> m;
          m.body_a = j;
          m.body_b = index;
          m.collider_a = ca;
          m.collider_b = cb;
          m.friction = std::sqrt(o.friction * b.friction);
          m.hand = o.type == BodyType::kinematic || b.type == BodyType::kinematic;
          manifolds_.push_back(m);
        }
    }
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
    if (collider_a < 0 || collider_a >= collider_count())
      detail::throw_invalid_argument("collider_a", "expected a collider index in [0, " +
                                                       std::to_string(collider_count()) +
                                                       "), got " + std::to_string(collider_a));
    if (collider_b < 0 || collider_b >= collider_count())
      detail::throw_invalid_argument("collider_b", "expected a collider index in [0, " +
                                                       std::to_string(collider_count()) +
                                                       "), got " + std::to_string(collider_b));
    require_non_negative(mu, "mu");
    if (mu > 1e6) detail::throw_invalid_argument("mu", "expected at most 1e6, got " + number(mu));
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
    require_body(body, "body");
    if (bodies_[static_cast<std::size_t>(body)].type != BodyType::kinematic)
      detail::throw_invalid_argument("body", "expected a kinematic body");
    require_finite(pose.matrix(), "pose");
    require_coordinates(pose.translation(), "pose");
    Target& t = targets_[static_cast<std::size_t>(body)];
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
    require_body(body, "body");
    require_finite(pose.matrix(), "pose");
    require_coordinates(pose.translation(), "pose");
    RigidBody<S>& b = bodies_[static_cast<std::size_t>(body)];
    b.R = orthonormalized(pose.linear().template cast<S>());
    b.q = detail::Quat<S>(b.R).normalized();
    b.R = b.q.toRotationMatrix();
    b.x = pose.translation().template cast<S>() + b.R * b.local_com;
    if (b.type == BodyType::dynamic) b.inv_inertia = b.R * b.inv_inertia_local * b.R.transpose();
    targets_[static_cast<std::size_t>(body)] = Target{b.R, b.x, false};
    update_colliders(body);
  }

  /// Sets the velocity of body \p body: \p v of its centre of mass (m/s) and \p w (rad/s), both
  /// in the world frame. Ignored for fixed bodies. Throws topograsp::invalid_argument for a bad
  /// index, non-finite values, or a speed |v| or |w| above StepperOptions::max_speed (which would
  /// end the run at the next step).
  void set_velocity(int body, const Eigen::Vector3d& v, const Eigen::Vector3d& w) {
    require_body(body, "body");
    require_finite(v, "v");
    require_finite(w, "w");
    if (!(v.norm() <= options_.max_speed))
      detail::throw_invalid_argument(
          "v", "expected a speed of at most options.max_speed = " + number(options_.max_speed) +
                   " m/s, got " + number(v.norm()));
    if (!(w.norm() <= options_.max_speed))
      detail::throw_invalid_argument(
          "w", "expected a speed of at most options.max_speed = " + number(options_.max_speed) +
                   " rad/s, got " + number(w.norm()));
    RigidBody<S>& b = bodies_[static_cast<std::size_t>(body)];
    if (b.type == BodyType::fixed) return;
    b.v = v.template cast<S>();
    b.w = w.template cast<S>();
  }

  /// Adds a joint-space actuator (see ActuatorDesc) and returns its index. Allocates. Throws
  /// topograsp::invalid_argument naming the field ("desc.inertia", ...) for a non-finite value,
  /// lower above upper, a position outside [lower, upper], or an inertia, max_effort,
  /// max_velocity or stiffness that is not positive, a negative damping_time; and for values S
  /// cannot hold (limits and
  /// position beyond max_length(), an inertia outside [min_length(), max_length()], a
  /// max_velocity above StepperOptions::max_speed).
  int add_actuator(const ActuatorDesc& desc) {
    require_finite(desc.position, "desc.position");
    require_finite(desc.lower, "desc.lower");
    require_finite(desc.upper, "desc.upper");
    if (desc.lower > desc.upper)
      detail::throw_invalid_argument(
          "desc.lower",
          "expected at most desc.upper = " + number(desc.upper) + ", got " + number(desc.lower));
    if (!(std::abs(desc.lower) <= static_cast<double>(max_length()) &&
          std::abs(desc.upper) <= static_cast<double>(max_length())))
      detail::throw_invalid_argument("desc.lower",
                                     "expected limits of at most " + number(max_length()));
    if (desc.position < desc.lower || desc.position > desc.upper)
      detail::throw_invalid_argument("desc.position", "expected a value in [" + number(desc.lower) +
                                                          ", " + number(desc.upper) + "], got " +
                                                          number(desc.position));
    require_actuator_inertia(desc.inertia, "desc.inertia");
    require_positive(desc.max_effort, "desc.max_effort");
    require_positive(desc.max_velocity, "desc.max_velocity");
    if (!(desc.max_velocity <= options_.max_speed))
      detail::throw_invalid_argument("desc.max_velocity", "expected at most options.max_speed = " +
                                                              number(options_.max_speed) +
                                                              ", got " + number(desc.max_velocity));
    require_positive(desc.stiffness, "desc.stiffness");
    require_non_negative(desc.damping_time, "desc.damping_time");
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
    require_actuator(a, "a");
    require_finite(target, "target");
    if (!(std::abs(target) <= static_cast<double>(max_length())))
      detail::throw_invalid_argument("target", "expected at most " + number(max_length()));
    actuators_[static_cast<std::size_t>(a)].target = static_cast<S>(target);
  }
  /// Sets the torque limit of actuator \p a's servo (N m or N, > 0). Throws
  /// topograsp::invalid_argument for a bad index or a value that is not positive and finite.
  void set_actuator_max_effort(int a, double max_effort) {
    require_actuator(a, "a");
    require_positive(max_effort, "max_effort");
    actuators_[static_cast<std::size_t>(a)].max_effort = static_cast<S>(max_effort);
  }
  /// Sets the inertia of actuator \p a (kg m^2 or kg), e.g. each step from the configuration.
  /// Throws topograsp::invalid_argument as ActuatorDesc::inertia is checked.
  void set_actuator_inertia(int a, double inertia) {
    require_actuator(a, "a");
    require_actuator_inertia(inertia, "inertia");
    detail::Actuator<S>& x = actuators_[static_cast<std::size_t>(a)];
    x.inertia = static_cast<S>(inertia);
    x.inv_inertia = S(1) / x.inertia;
  }
  /// Sets the external generalised force on actuator \p a for the next steps (N m or N; e.g.
  /// the weight of the links it carries). Throws topograsp::invalid_argument for a bad index or
  /// a non-finite value.
  void set_actuator_force(int a, double force) {
    require_actuator(a, "a");
    require_finite(force, "force");
    actuators_[static_cast<std::size_t>(a)].force = static_cast<S>(force);
  }
  /// Puts actuator \p a at \p position at once, at rest, with its target there and its
  /// accumulated impulses cleared. Throws topograsp::invalid_argument for a bad index or a
  /// position outside its limits.
  void set_actuator_position(int a, double position) {
    require_actuator(a, "a");
    detail::Actuator<S>& x = actuators_[static_cast<std::size_t>(a)];
    require_finite(position, "position");
    if (position < static_cast<double>(x.lower) || position > static_cast<double>(x.upper))
      detail::throw_invalid_argument("position", "expected a value in [" + number(x.lower) + ", " +
                                                     number(x.upper) + "], got " +
                                                     number(position));
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
    require_body(body, "body");
    if (bodies_[static_cast<std::size_t>(body)].type != BodyType::kinematic)
      detail::throw_invalid_argument("body", "expected a kinematic body");
    if (joints.size() > static_cast<std::size_t>(k_max_body_joints))
      detail::throw_invalid_argument("joints", "expected at most " +
                                                   std::to_string(k_max_body_joints) +
                                                   " joints, got " + std::to_string(joints.size()));
    detail::BodyJoints<S>& out = joints_[static_cast<std::size_t>(body)];
    for (std::size_t j = 0; j < joints.size(); ++j) {
      // Checked without building a name first: this runs every step and allocates nothing.
      const BodyJoint& in = joints[j];
      const auto name = [j](std::string_view field) {
        return "joints[" + std::to_string(j) + "]." + std::string(field);
      };
      if (in.actuator < 0 || in.actuator >= actuator_count())
        require_actuator(in.actuator, name("actuator"));
      if (!in.axis.allFinite() || !(std::abs(in.axis.norm() - 1.0) <= 1e-6))
        detail::throw_invalid_argument(name("axis"), "expected a finite unit vector");
      if (!in.origin.allFinite() ||
          !(in.origin.cwiseAbs().maxCoeff() <= static_cast<double>(max_length())))
        detail::throw_invalid_argument(name("origin"), "expected finite coordinates of at most " +
                                                           number(max_length()) + " m");
      if (!std::isfinite(in.gear))
        detail::throw_invalid_argument(name("gear"), "expected a finite number");
    }
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
  /// velocity ramp of kinematic_substep()): for a body carried by actuators, placed after each
  /// step where they took it. Throws as set_pose() does, and for a body that is not kinematic.
  void move_kinematic(int body, const Eigen::Isometry3d& pose) {
    require_body(body, "body");
    if (bodies_[static_cast<std::size_t>(body)].type != BodyType::kinematic)
      detail::throw_invalid_argument("body", "expected a kinematic body");
    require_finite(pose.matrix(), "pose");
    require_coordinates(pose.translation(), "pose");
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
    require_step_catches_fall(g, "g");
    gravity_ = g.template cast<S>();
  }
  [[nodiscard]] V3 gravity() const noexcept { return gravity_; }

  /// Advances the world by one time step (see the class comment). Allocates nothing. Returns
  /// Status::success, or Status::numerical_issue when the state became non-finite, too fast or too
  /// far (beyond max_length()); then
  /// the step is undone (every number stays finite) and later calls do nothing and return it again.
  Status step() noexcept {
    if (status_ != Status::success) return status_;
    const S dt = static_cast<S>(options_.time_step);
    const int n_sub = options_.substeps;
    const S h = dt / static_cast<S>(n_sub);
    save_state();
    for (detail::Actuator<S>& a : actuators_) {
      a.q0 = a.q;
      a.step_impulse = S(0);
    }
    drive_kinematic(dt);
    find_contacts();
    detail::prepare_contacts<S>(manifolds_, bodies_, joints_, actuators_, options_, h);
    const S push = static_cast<S>(options_.contact_push_max_speed);
    const S lin_damp = S(1) / (S(1) + h * static_cast<S>(options_.linear_damping));
    const S ang_damp = S(1) / (S(1) + h * static_cast<S>(options_.angular_damping));
    for (int sub = 0; sub < n_sub; ++sub) {
      kinematic_substep(sub, n_sub);
      for (RigidBody<S>& b : bodies_) {
        if (b.type != BodyType::dynamic) continue;
        b.v = lin_damp * (b.v + h * gravity_);
        b.w *= ang_damp;
      }
      for (detail::Actuator<S>& a : actuators_) a.qd += h * a.force * a.inv_inertia;
      detail::warm_start_actuators<S>(actuators_);
      detail::warm_start_contacts<S>(manifolds_, bodies_, joints_, actuators_);
      update_turned();
      for (int it = 0; it < options_.iterations; ++it) {
        detail::solve_actuators<S>(actuators_, h, true, push);
        detail::solve_contacts<S>(manifolds_, bodies_, joints_, actuators_, turned_, options_, h,
                                  true);
      }
      integrate_positions(h);
      for (detail::Actuator<S>& a : actuators_) a.q += h * a.qd;
      update_turned();
      for (int it = 0; it < options_.iterations; ++it) {
        detail::solve_actuators<S>(actuators_, h, false, push);
        detail::solve_contacts<S>(manifolds_, bodies_, joints_, actuators_, turned_, options_, h,
                                  false);
      }
      detail::accumulate_impulses<S>(manifolds_);
      for (detail::Actuator<S>& a : actuators_) a.step_impulse += a.motor_impulse;
    }
    finish_kinematic();
    for (int i = 0; i < static_cast<int>(bodies_.size()); ++i) update_colliders(i);
    detail::store_impulses<S>(manifolds_);
    if (!state_ok()) {
      restore_state();
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
  [[nodiscard]] int body_count() const noexcept { return static_cast<int>(bodies_.size()); }
  /// Every contact slot; those with count > 0 touched (or nearly) in the last step.
  [[nodiscard]] std::span<const Manifold<S>> manifolds() const noexcept { return manifolds_; }
  /// The shape \p i.
  [[nodiscard]] const Collider<S>& collider(int i) const noexcept {
    TOPOGRASP_ASSERT(i >= 0 && i < collider_count(), "collider index out of range");
    return colliders_[static_cast<std::size_t>(i)];
  }
  [[nodiscard]] int collider_count() const noexcept { return static_cast<int>(colliders_.size()); }

  /// The number of contact points between bodies \p a and \p b (either order) at the last step
  /// whose separation was at most \p max_separation (m).
  [[nodiscard]] int contact_count(int a, int b, S max_separation = S(0)) const noexcept {
    int n = 0;
    for (const Manifold<S>& m : manifolds_)
      if ((m.body_a == a && m.body_b == b) || (m.body_a == b && m.body_b == a))
        for (int k = 0; k < m.count; ++k)
          if (m.points[static_cast<std::size_t>(k)].separation <= max_separation) ++n;
    return n;
  }

  /// The total normal impulse (N s) between bodies \p a and \p b over the last step.
  [[nodiscard]] S normal_impulse(int a, int b) const noexcept {
    S sum = S(0);
    for (const Manifold<S>& m : manifolds_)
      if ((m.body_a == a && m.body_b == b) || (m.body_a == b && m.body_b == a))
        for (int k = 0; k < m.count; ++k) sum += m.points[static_cast<std::size_t>(k)].step_impulse;
    return sum;
  }

  [[nodiscard]] const StepperOptions& options() const noexcept { return options_; }
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
    return view(colliders_[static_cast<std::size_t>(i)]);
  }

 private:
  struct Target {
    M3 R;
    V3 p;
    bool active = false;
    V3 v = V3::Zero(), w = V3::Zero();            // this step's chord velocities
    V3 prev_v = V3::Zero(), prev_w = V3::Zero();  // the previous step's
  };
  struct Saved {
    V3 x = V3::Zero(), v = V3::Zero(), w = V3::Zero();
    detail::Quat<S> q = detail::Quat<S>::Identity();
    M3 R = M3::Identity();
  };

  static void require_pose(const Pose& pose, std::string_view argument) {
    for (double v : pose.R) require_finite(v, argument);
    for (double v : pose.p) require_finite(v, argument);
    const Mat3 R = pose.rotation();
    if (!(R.transpose() * R).isApprox(Mat3::Identity(), 1e-6) || R.determinant() < 0.0)
      detail::throw_invalid_argument(argument, "expected a rotation (orthonormal, det +1)");
  }
  void require_actuator(int a, std::string_view argument) const {
    if (a < 0 || a >= static_cast<int>(actuators_.size()))
      detail::throw_invalid_argument(argument, "expected an actuator index in [0, " +
                                                   std::to_string(actuators_.size()) + "), got " +
                                                   std::to_string(a));
  }
  static void require_actuator_inertia(double inertia, std::string_view argument) {
    require_positive(inertia, argument);
    if (!(inertia >= static_cast<double>(min_length()) &&
          inertia <= static_cast<double>(max_length())))
      detail::throw_invalid_argument(argument, "expected a value in [" + number(min_length()) +
                                                   ", " + number(max_length()) + "], got " +
                                                   number(inertia));
  }
  void require_body(int body, std::string_view argument) const {
    if (body < 0 || body >= static_cast<int>(bodies_.size()))
      detail::throw_invalid_argument(argument, "expected a body index in [0, " +
                                                   std::to_string(bodies_.size()) + "), got " +
                                                   std::to_string(body));
  }
  template <class T>
  static std::string number(T v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", static_cast<double>(v));
    return buf;
  }
  void require_step_catches_fall(const Eigen::Vector3d& g, std::string_view argument) const {
    const double dt = options_.time_step;
    const double fall = g.norm() * dt * dt;
    if (!(fall <= options_.speculative_distance))
      detail::throw_invalid_argument(
          argument, "a body released at rest falls |g| dt^2 = " + number(fall) +
                        " m in one step, more than options.speculative_distance = " +
                        number(options_.speculative_distance) +
                        " m, so contacts would miss it (time_step " + number(dt) + " s, |g| " +
                        number(g.norm()) + " m/s^2): use a shorter time step");
  }
  template <class D>
  static void require_coordinates(const Eigen::MatrixBase<D>& p, std::string_view argument) {
    for (Eigen::Index k = 0; k < p.size(); ++k)
      if (!(std::abs(static_cast<double>(p[k])) <= static_cast<double>(max_length())))
        detail::throw_invalid_argument(argument, "expected coordinates of at most " +
                                                     number(max_length()) + " m, got " +
                                                     number(static_cast<double>(p[k])));
  }
  static void require_coordinates(const std::array<double, 3>& p, std::string_view argument) {
    require_coordinates(Eigen::Map<const Eigen::Vector3d>(p.data()), argument);
  }
  static void require_representable_shape(const ShapeSpec& s, const std::string& argument) {
    const int n = s.type == ShapeType::sphere ? 1 : s.type == ShapeType::box ? 3 : 2;
    for (int k = 0; k < n; ++k) {
      const double v = s.size[static_cast<std::size_t>(k)];
      if (v == 0.0 && s.type == ShapeType::capsule && k == 1)
        continue;  // a capsule may be a sphere
      if (!(v >= static_cast<double>(min_length()) && v <= static_cast<double>(max_length())))
        detail::throw_invalid_argument(argument + ".size[" + std::to_string(k) + "]",
                                       "expected a size in [" + number(min_length()) + ", " +
                                           number(max_length()) + "] m, got " + number(v));
    }
    require_coordinates(s.pose.p, argument + ".pose");
  }
  // A given inertial must be one a rigid body can have (as MuJoCo's mj_setConst checks).
  static void require_physical_inertial(const MassProperties<double>& m, const std::string& arg) {
    require_positive(m.mass, arg + ".mass");
    if (!m.com.allFinite()) detail::throw_invalid_argument(arg + ".com", "expected finite numbers");
    const Mat3& I = m.inertia;
    if (!I.allFinite() || !I.isApprox(I.transpose(), 1e-9))
      detail::throw_invalid_argument(arg + ".inertia", "expected a finite symmetric matrix");
    const Vec3 e = Eigen::SelfAdjointEigenSolver<Mat3>(I).eigenvalues();
    if (!(e[0] > 0.0) || e[0] + e[1] < e[2] * (1.0 - 1e-9))
      detail::throw_invalid_argument(arg + ".inertia",
                                     "expected positive principal moments with A + B >= C, got " +
                                         number(e[0]) + ", " + number(e[1]) + ", " + number(e[2]) +
                                         " kg m^2");
  }
  void require_representable_mass(const RigidBody<S>& b, std::string_view argument) const {
    const S smin = std::numeric_limits<S>::min(), smax = std::numeric_limits<S>::max();
    const S v2 = static_cast<S>(options_.max_speed) * static_cast<S>(options_.max_speed);
    const bool mass_ok = std::isfinite(b.mass) && b.mass >= smin && std::isfinite(b.inv_mass) &&
                         b.mass <= smax / v2 && b.local_com.allFinite();
    if (!mass_ok)
      detail::throw_invalid_argument(
          argument, "the body's mass " + number(static_cast<double>(b.mass)) +
                        " kg is not representable: expected a normal positive number whose "
                        "kinetic energy at options.max_speed stays finite, within [" +
                        number(static_cast<double>(smin)) + ", " +
                        number(static_cast<double>(smax / v2)) + "] kg");
    bool inertia_ok =
        b.inertia.allFinite() && b.inv_inertia_local.allFinite() && b.inv_inertia.allFinite();
    for (int k = 0; k < 3 && inertia_ok; ++k)
      inertia_ok = b.inertia(k, k) >= smin && b.inertia(k, k) <= smax / v2 &&
                   b.inv_inertia_local(k, k) > S(0);
    if (!inertia_ok)
      detail::throw_invalid_argument(
          argument, "the body's inertia (diagonal " + number(static_cast<double>(b.inertia(0, 0))) +
                        ", " + number(static_cast<double>(b.inertia(1, 1))) + ", " +
                        number(static_cast<double>(b.inertia(2, 2))) +
                        " kg m^2) is not representable: expected normal positive numbers with a "
                        "finite inverse whose kinetic energy at options.max_speed stays finite, "
                        "within [" +
                        number(static_cast<double>(smin)) + ", " +
                        number(static_cast<double>(smax / v2)) + "] kg m^2");
  }
  // The inverse of a symmetric positive definite 3x3 matrix. Eigen's closed-form inverse forms
  // products of three entries, which overflow or underflow for entries beyond about 1e100 (or
  // 1e12 in float): outside [2^-k, 2^k], k a sixth of the exponent range of S, the matrix is
  // first scaled by an exact power of two, inv(A) = 2^-e inv(A 2^-e). Inside, the plain inverse.
  static M3 inverse_in_range(const M3& A) {
    const S m = A.cwiseAbs().maxCoeff();
    constexpr int k = std::numeric_limits<S>::max_exponent / 6;
    if (!(m > S(0)) || !std::isfinite(m) || (m >= std::ldexp(S(1), -k) && m <= std::ldexp(S(1), k)))
      return A.inverse();
    int e = 0;
    (void)std::frexp(m, &e);
    return M3(M3(A * std::ldexp(S(1), -e)).inverse() * std::ldexp(S(1), -e));
  }
  static M3 orthonormalized(const M3& R) noexcept {
    return detail::Quat<S>(R).normalized().toRotationMatrix();
  }

  void update_colliders(int i) noexcept {
    const RigidBody<S>& b = bodies_[static_cast<std::size_t>(i)];
    for (int c = b.first_collider; c < b.first_collider + b.n_colliders; ++c) {
      Collider<S>& col = colliders_[static_cast<std::size_t>(c)];
      col.R.noalias() = b.R * col.local_R;
      col.p = b.x + b.R * col.local_p;
    }
  }

  void save_state() noexcept {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      const RigidBody<S>& b = bodies_[i];
      saved_[i] = {b.x, b.v, b.w, b.q, b.R};
    }
    for (std::size_t i = 0; i < actuators_.size(); ++i) saved_actuators_[i] = actuators_[i];
  }
  void restore_state() noexcept {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      RigidBody<S>& b = bodies_[i];
      b.x = saved_[i].x;
      b.v = saved_[i].v;
      b.w = saved_[i].w;
      b.q = saved_[i].q;
      b.R = b.q.toRotationMatrix();
      if (b.type == BodyType::dynamic) b.inv_inertia = b.R * b.inv_inertia_local * b.R.transpose();
      update_colliders(static_cast<int>(i));
    }
    for (std::size_t i = 0; i < actuators_.size(); ++i) actuators_[i] = saved_actuators_[i];
  }
  [[nodiscard]] bool state_ok() const noexcept {
    const S vmax = static_cast<S>(options_.max_speed);
    const S xmax = max_length();
    for (const RigidBody<S>& b : bodies_) {
      if (b.type != BodyType::dynamic) continue;
      if (!b.x.allFinite() || !b.v.allFinite() || !b.w.allFinite() || !b.q.coeffs().allFinite())
        return false;
      if (b.v.norm() > vmax || b.w.norm() > vmax) return false;
      if (b.x.cwiseAbs().maxCoeff() > xmax) return false;
    }
    for (const detail::Actuator<S>& a : actuators_)
      if (!std::isfinite(a.q) || !std::isfinite(a.qd) || std::abs(a.qd) > vmax) return false;
    return true;
  }

  // Kinematic bodies: the constant velocity that reaches the target in one step.
  void drive_kinematic(S dt) noexcept {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      RigidBody<S>& b = bodies_[i];
      Target& t = targets_[i];
      if (b.type != BodyType::kinematic || !t.active) continue;
      t.v = (t.p - b.x) / dt;
      t.w = detail::log_rotation<S>(M3(t.R * b.R.transpose())) / dt;
    }
  }
  // The velocity of a kinematic body in sub-step s of n. The targets are samples of a smooth
  // path: the chord velocity u of this step is the velocity at its middle, and the velocity
  // changes linearly through the step at the rate (u - u_prev) / dt, continuous across steps for
  // a path of constant acceleration (a turning hand). The sub-step velocities average to u, so
  // the body still reaches its target. A constant velocity per step instead would turn the
  // velocity abruptly at each step, a demand friction can meet only within one sub-step.
  void kinematic_substep(int s, int n) noexcept {
    const S c = (static_cast<S>(s) + S(0.5)) / static_cast<S>(n) - S(0.5);
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      RigidBody<S>& b = bodies_[i];
      const Target& t = targets_[i];
      if (b.type != BodyType::kinematic || !t.active) continue;
      b.v = t.v + c * (t.v - t.prev_v);
      b.w = t.w + c * (t.w - t.prev_w);
    }
  }
  void finish_kinematic() noexcept {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
      RigidBody<S>& b = bodies_[i];
      Target& t = targets_[i];
      if (b.type != BodyType::kinematic) continue;
      if (!t.active) {
        t.prev_v.setZero();
        t.prev_w.setZero();
        continue;
      }
      b.x = t.p;
      b.q = detail::Quat<S>(t.R).normalized();
      b.R = b.q.toRotationMatrix();
      b.v.setZero();
      b.w.setZero();
      t.prev_v = t.v;
      t.prev_w = t.w;
      t.active = false;
    }
  }

  [[nodiscard]] ShapeView<S> view(const Collider<S>& c) const noexcept {
    ShapeView<S> v;
    v.type = c.type;
    v.size = c.size;
    v.R = c.R;
    v.p = c.p;
    TOPOGRASP_ASSERT(
        (c.polytope >= 0) == (c.type == ShapeType::box || c.type == ShapeType::cylinder),
        "boxes and cylinders, and only they, have a polytope");
    v.polytope = c.polytope >= 0 ? &polytopes_[static_cast<std::size_t>(c.polytope)] : nullptr;
    return v;
  }

  // A contact point lies midway between the two surfaces. When the smaller shape lies deep inside
  // the larger one (a sphere of radius 1e127 around a ball of 0.4 m: an overlap of 1e127 m) that
  // point lies far outside both bodies, and its lever arms turn the solver's impulses into
  // overflow. Points farther than twice the smaller shape's bounding radius (plus the margin)
  // from its centre are moved back to that distance along the same line; no overlap shallower
  // than the smaller shape's own size is touched.
  static void keep_points_near(const Collider<S>& ca, const Collider<S>& cb, S margin,
                               ContactSet<S>& cs) noexcept {
    const Collider<S>& small = ca.bounding_radius <= cb.bounding_radius ? ca : cb;
    const S reach = S(2) * small.bounding_radius + margin;
    for (int k = 0; k < cs.count; ++k) {
      V3& p = cs.points[static_cast<std::size_t>(k)].point;
      const V3 d = p - small.p;
      const S r = d.norm();
      if (r > reach) p = small.p + d * (reach / r);
    }
  }

  // The narrow phase on every pair whose bounding spheres are within the margin, with each new
  // point matched to the previous step's by feature id (match_contacts()).
  void find_contacts() noexcept {
    const S margin = static_cast<S>(options_.speculative_distance);
    for (Manifold<S>& m : manifolds_) {
      const Collider<S>& ca = colliders_[static_cast<std::size_t>(m.collider_a)];
      const Collider<S>& cb = colliders_[static_cast<std::size_t>(m.collider_b)];
      const S reach = ca.bounding_radius + cb.bounding_radius + margin;
      if ((ca.p - cb.p).squaredNorm() > reach * reach) {
        m.count = 0;
        m.twist_impulse = S(0);
        continue;
      }
      ContactSet<S> cs;
      collide<S>(view(ca), view(cb), margin, cs);
      keep_points_near(ca, cb, margin, cs);
      match_contacts<S>(m, cs);
    }
  }

  // How far each body has turned since the step began (the contact solver's frame rotation).
  void update_turned() noexcept {
    TOPOGRASP_ASSERT(turned_.size() == bodies_.size() && saved_.size() == bodies_.size(),
                     "one scratch rotation and one saved state per body");
    for (std::size_t i = 0; i < bodies_.size(); ++i)
      turned_[i] = bodies_[i].type == BodyType::fixed ? M3::Identity()
                                                      : M3(bodies_[i].R * saved_[i].R.transpose());
  }

  void integrate_positions(S h) noexcept {
    for (RigidBody<S>& b : bodies_) {
      if (b.type == BodyType::fixed) continue;
      b.x += h * b.v;
      if (b.w.squaredNorm() > S(0)) {
        b.q = (detail::exp_rotation<S>(V3(h * b.w)) * b.q).normalized();
        b.R = b.q.toRotationMatrix();
        if (b.type == BodyType::dynamic)
          b.inv_inertia = b.R * b.inv_inertia_local * b.R.transpose();
      }
    }
  }

  StepperOptions options_;
  V3 gravity_ = V3::Zero();
  std::vector<RigidBody<S>> bodies_;
  std::vector<Target> targets_;
  std::vector<Saved> saved_;
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
