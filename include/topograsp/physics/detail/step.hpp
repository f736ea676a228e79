// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// One step of a World as stages over a step context (internal), as Box2D v3 stages its solver:
/// StepContext is built once a step by World::step() and every stage reads it; the stages here move
/// bodies and actuators (kinematic targets, velocities, positions), the contact stages are in
/// physics/contact_solver.hpp. None allocates. docs/architecture.md, "Adding a physics stage".
#pragma once

#include <span>

#include <topograsp/core/eigen.hpp>
#include <topograsp/physics/actuator.hpp>
#include <topograsp/physics/detail/math.hpp>
#include <topograsp/physics/rigid_body.hpp>
#include <topograsp/physics/stepper_options.hpp>

namespace topograsp::detail {

/// What every stage of one step reads: the world's bodies, the joints that carry its kinematic
/// bodies, its actuators and each body's rotation since the step began, its options, and the
/// step's constants. Built by World::step() once a step; the spans stay valid through the step
/// (nothing is added to a World while it steps).
template <class S>
struct StepContext {
  std::span<RigidBody<S>> bodies;
  std::span<const BodyJoints<S>> joints;  ///< one per body; count 0 unless actuators carry it
  std::span<Actuator<S>> actuators;
  std::span<const Mat<3, 3, S>> turned;  ///< each body's rotation since the step began
  const StepperOptions& options;
  Vec<3, S> gravity;
  S dt;               ///< the step (s)
  int substeps;       ///< sub-steps in the step
  S h;                ///< the sub-step, dt / substeps (s)
  S inv_h;            ///< 1 / h
  S push;             ///< options.contact_push_max_speed: rigid contacts' and limits' largest push
  S linear_damping;   ///< per sub-step factor of linear velocities, 1 / (1 + h c)
  S angular_damping;  ///< and of angular velocities
};

/// The context of a step of \p options with \p gravity over the world's arrays.
template <class S>
[[nodiscard]] StepContext<S> make_step_context(std::span<RigidBody<S>> bodies,
                                               std::span<const BodyJoints<S>> joints,
                                               std::span<Actuator<S>> actuators,
                                               std::span<const Mat<3, 3, S>> turned,
                                               const StepperOptions& options,
                                               const Vec<3, S>& gravity) noexcept {
  const S dt = static_cast<S>(options.time_step);
  const int n_sub = options.substeps;
  const S h = dt / static_cast<S>(n_sub);
  return StepContext<S>{bodies,
                        joints,
                        actuators,
                        turned,
                        options,
                        gravity,
                        dt,
                        n_sub,
                        h,
                        S(1) / h,
                        static_cast<S>(options.contact_push_max_speed),
                        S(1) / (S(1) + h * static_cast<S>(options.linear_damping)),
                        S(1) / (S(1) + h * static_cast<S>(options.angular_damping))};
}

/// Where a kinematic body goes this step and how it moved the last: World::set_target()'s pose,
/// this step's chord velocities and the previous step's.
template <class S>
struct KinematicTarget {
  Mat<3, 3, S> R;
  Vec<3, S> p;
  bool active = false;
  Vec<3, S> v = Vec<3, S>::Zero(), w = Vec<3, S>::Zero();  ///< this step's chord velocities
  Vec<3, S> prev_v = Vec<3, S>::Zero(), prev_w = Vec<3, S>::Zero();  ///< the previous step's
};

/// Stage 0, once a step: each actuator's position at the step's start, its step impulse cleared.
template <class S>
void begin_actuator_step(const StepContext<S>& ctx) noexcept {
  for (Actuator<S>& a : ctx.actuators) {
    a.q0 = a.q;
    a.step_impulse = S(0);
  }
}

/// Stage 1, once a step: kinematic bodies with a target get the constant velocity that reaches it
/// in one step (the chord velocity).
template <class S>
void drive_kinematic(const StepContext<S>& ctx, std::span<KinematicTarget<S>> targets) noexcept {
  for (std::size_t i = 0; i < ctx.bodies.size(); ++i) {
    RigidBody<S>& b = ctx.bodies[i];
    KinematicTarget<S>& t = targets[i];
    if (b.type != BodyType::kinematic || !t.active) continue;
    t.v = (t.p - b.x) / ctx.dt;
    t.w = log_rotation<S>(Mat<3, 3, S>(t.R * b.R.transpose())) / ctx.dt;
  }
}

/// Every sub-step \p s: the velocity of each kinematic body. The targets are samples of a smooth
/// path: the chord velocity u of this step is the velocity at its middle, and the velocity changes
/// linearly through the step at the rate (u - u_prev) / dt, continuous across steps for a path of
/// constant acceleration (a turning hand). The sub-step velocities average to u, so the body still
/// reaches its target. A constant velocity per step instead would turn the velocity abruptly at
/// each step, a demand friction can meet only within one sub-step.
template <class S>
void kinematic_substep(const StepContext<S>& ctx, std::span<const KinematicTarget<S>> targets,
                       int s) noexcept {
  const S c = (static_cast<S>(s) + S(0.5)) / static_cast<S>(ctx.substeps) - S(0.5);
  for (std::size_t i = 0; i < ctx.bodies.size(); ++i) {
    RigidBody<S>& b = ctx.bodies[i];
    const KinematicTarget<S>& t = targets[i];
    if (b.type != BodyType::kinematic || !t.active) continue;
    b.v = t.v + c * (t.v - t.prev_v);
    b.w = t.w + c * (t.w - t.prev_w);
  }
}

/// Every sub-step: gravity and damping on the dynamic bodies, the external forces on the
/// actuators.
template <class S>
void integrate_velocities(const StepContext<S>& ctx) noexcept {
  for (RigidBody<S>& b : ctx.bodies) {
    if (b.type != BodyType::dynamic || b.held) continue;
    b.v = ctx.linear_damping * (b.v + ctx.h * ctx.gravity);
    b.w *= ctx.angular_damping;
  }
  for (Actuator<S>& a : ctx.actuators) a.qd += ctx.h * a.force * a.inv_inertia;
}

/// Every sub-step, between the biased solve and the relax: positions by semi-implicit Euler,
/// rotations by the exact exponential, actuators' positions by their velocities.
template <class S>
void integrate_positions(const StepContext<S>& ctx) noexcept {
  for (RigidBody<S>& b : ctx.bodies) {
    if (b.type == BodyType::fixed) continue;
    b.x += ctx.h * b.v;
    if (b.w.squaredNorm() > S(0)) {
      b.q = (exp_rotation<S>(Vec<3, S>(ctx.h * b.w)) * b.q).normalized();
      b.R = b.q.toRotationMatrix();
      b.update_world_inertia();
    }
  }
  for (Actuator<S>& a : ctx.actuators) a.q += ctx.h * a.qd;
}

/// After each sub-step's relax: each actuator's motor impulse added to its step total.
template <class S>
void end_actuator_substep(const StepContext<S>& ctx) noexcept {
  for (Actuator<S>& a : ctx.actuators) a.step_impulse += a.motor_impulse;
}

/// Once a step, at its end: kinematic bodies placed exactly at their targets, at rest; the chord
/// velocities kept for the next step's ramp (cleared for a body without a target).
template <class S>
void finish_kinematic(const StepContext<S>& ctx, std::span<KinematicTarget<S>> targets) noexcept {
  for (std::size_t i = 0; i < ctx.bodies.size(); ++i) {
    RigidBody<S>& b = ctx.bodies[i];
    KinematicTarget<S>& t = targets[i];
    if (b.type != BodyType::kinematic) continue;
    if (!t.active) {
      t.prev_v.setZero();
      t.prev_w.setZero();
      continue;
    }
    b.x = t.p;
    b.q = Quat<S>(t.R).normalized();
    b.R = b.q.toRotationMatrix();
    b.v.setZero();
    b.w.setZero();
    t.prev_v = t.v;
    t.prev_w = t.w;
    t.active = false;
  }
}

}  // namespace topograsp::detail
