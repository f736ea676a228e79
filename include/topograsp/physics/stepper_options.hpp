// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// StepperOptions: every parameter of the rigid-body stepper, each with its default and unit.
#pragma once

#include <array>

#include <topograsp/core/constants.hpp>
#include <topograsp/core/parameters.hpp>

namespace topograsp {

/// The parameters of a World: time step, solver, contact softness and friction. Every field has a
/// documented default; default_stepper_options() returns them. Units are SI.
///
/// Contacts come in two kinds. Contacts between a kinematic body (a hand link) and a dynamic body
/// (the object) are physical spring-dampers, the compliance of a finger pad: the force is
/// kinematic_stiffness times the overlap. What a finger presses with is set by its motor's torque
/// limit (World::add_actuator()); the stiffness only sets how far the pad gives under it.
/// Every other contact (dynamic-dynamic, dynamic-static) is a "rigid" soft contact in the sense of
/// Box2D v3: its stiffness is given as a frequency that scales with the effective mass, so it
/// behaves the same for a 10 g and a 10 kg body.
struct StepperOptions {
  /// The fixed time step (s). Default 1/60 s, the shake test's step.
  double time_step = 1.0 / 60.0;
  /// Sub-steps per step: each integrates velocities, warm starts, solves with bias, integrates
  /// positions and relaxes without bias. More sub-steps make stiff contacts and stacks more
  /// accurate at a linear cost. 1 to 1000. Default 4.
  int substeps = 4;
  /// Gauss-Seidel passes over the actuator and contact rows in each solve of a sub-step (the
  /// biased solve and the relax). One suffices for bodies of similar mass (Box2D v3 uses one and
  /// prefers sub-steps); a hand's light finger joints pressing on a heavier object (effective
  /// masses 1000 times apart) need several to converge, or the grasp jitters. 1 to 100.
  /// Default 1; HandSceneOptions uses 4.
  int iterations = 1;
  /// Gravity in the world frame (m/s^2). Default (0, 0, -9.80665).
  std::array<double, 3> gravity{0.0, 0.0, -standard_gravity};

  /// Stiffness of rigid soft contacts as a frequency (Hz); capped at a quarter of the sub-step
  /// rate, where the implicit soft constraint stops being accurate. Default 30 Hz.
  double contact_hertz = 30.0;
  /// Damping ratio of rigid soft contacts (1 = critical). Box2D's default of 10 (heavily
  /// over-damped) keeps resting contacts from bouncing. Default 10.
  double contact_damping_ratio = 10.0;
  /// The largest speed (m/s) at which a rigid contact pushes overlapping bodies apart, so that a
  /// deep overlap never explodes. Default 3 m/s.
  double contact_push_max_speed = 3.0;

  /// Stiffness (N/m) of a contact between a kinematic and a dynamic body, per pair of shapes,
  /// shared evenly among the pair's contact points: the steady normal force is kinematic_stiffness
  /// times the overlap. Default 2000 N/m (2 N per mm of overlap, a soft-fingertip value: the SDH's
  /// rubber pads and a human fingertip both give about 1 to 5 N/mm).
  double kinematic_stiffness = 2000.0;
  /// Damping ratio of those contacts relative to the contact's effective mass (1 = critical);
  /// the damping coefficient is 2 zeta sqrt(k m_eff) (N s/m). Default 1.
  double kinematic_damping_ratio = 1.0;
  /// The largest speed (m/s) at which a kinematic body's contact pushes a dynamic body out of an
  /// overlap.
  /// Default 1 m/s.
  double kinematic_push_max_speed = 1.0;
  /// Radius (m) of the torsional friction of kinematic bodies' contacts (a soft-finger model): each
  /// contact
  /// pair resists spinning about its normal with a torque of at most mu * radius * normal force.
  /// Without it two fingertips cannot stop an object swinging about the line between them.
  /// 0 disables it. Default 0.003 m (two thirds of a 4.5 mm contact patch).
  double torsional_friction_radius = 0.003;

  /// Contacts are created for pairs whose surfaces are closer than this distance (m), so that the
  /// solver can stop an approach within one step ("speculative" contacts); they push only if the
  /// gap would close within the sub-step. Default 0.005 m.
  double speculative_distance = 0.005;
  /// A dynamic body faster than this (m/s or rad/s) or with a non-finite state ends the run with
  /// Status::numerical_issue: the step is undone and the world stops. Default 100.
  double max_speed = 100.0;
  /// Linear damping (1/s) of dynamic bodies: v *= 1 / (1 + h * damping) each sub-step. Default 0.
  double linear_damping = 0.0;
  /// Angular damping (1/s) of dynamic bodies, like linear_damping. Default 0.
  double angular_damping = 0.0;
};

/// The numeric fields of StepperOptions with their valid ranges (World's constructor checks
/// them, and that time_step and max_speed suit the scalar type; gravity is checked apart).
inline constexpr ParameterTable<StepperOptions, 14> stepper_parameters{{
    {"time_step", &StepperOptions::time_step, 0.0, unbounded, "s: the fixed time step", true},
    {"substeps", &StepperOptions::substeps, 1, 1000, "sub-steps per step"},
    {"iterations", &StepperOptions::iterations, 1, 100, "Gauss-Seidel passes per solve"},
    {"contact_hertz", &StepperOptions::contact_hertz, 0.0, unbounded,
     "Hz: stiffness of rigid soft contacts", true},
    {"contact_damping_ratio", &StepperOptions::contact_damping_ratio, 0.0, unbounded,
     "damping ratio of rigid soft contacts"},
    {"contact_push_max_speed", &StepperOptions::contact_push_max_speed, 0.0, unbounded,
     "m/s: largest push-out speed of rigid contacts", true},
    {"kinematic_stiffness", &StepperOptions::kinematic_stiffness, 0.0, unbounded,
     "N/m: stiffness of kinematic-dynamic contacts"},
    {"kinematic_damping_ratio", &StepperOptions::kinematic_damping_ratio, 0.0, unbounded,
     "damping ratio of kinematic-dynamic contacts"},
    {"kinematic_push_max_speed", &StepperOptions::kinematic_push_max_speed, 0.0, unbounded,
     "m/s: largest push-out speed of kinematic contacts", true},
    {"torsional_friction_radius", &StepperOptions::torsional_friction_radius, 0.0, unbounded,
     "m: radius of the kinematic contacts' torsional friction"},
    {"speculative_distance", &StepperOptions::speculative_distance, 0.0, unbounded,
     "m: contacts are made within this gap"},
    {"max_speed", &StepperOptions::max_speed, 0.0, unbounded,
     "m/s or rad/s: a faster dynamic body ends the run", true},
    {"linear_damping", &StepperOptions::linear_damping, 0.0, unbounded,
     "1/s: linear damping of dynamic bodies"},
    {"angular_damping", &StepperOptions::angular_damping, 0.0, unbounded,
     "1/s: angular damping of dynamic bodies"},
}};

/// The default options (the field initialisers of StepperOptions).
[[nodiscard]] inline StepperOptions default_stepper_options() noexcept { return {}; }

}  // namespace topograsp
