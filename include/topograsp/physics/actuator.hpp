// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Joint-space actuators of a World: the degrees of freedom of a hand's joints, each driven by a
/// torque-limited servo and held within its limits, and the joints that carry a kinematic body
/// (a hand link) on them, through which contacts push back on the actuators.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <span>

#include <topograsp/core/assert.hpp>
#include <topograsp/physics/detail/math.hpp>

namespace topograsp {

/// What World::add_actuator() builds an actuator from: one degree of freedom in joint space (a
/// revolute joint's angle, rad, or a prismatic joint's offset, m) with its own inertia, limits and
/// a servo. The servo is a position controller with a torque limit, as MuJoCo's position
/// actuator with forcerange and Box2D v3's motor with maxMotorTorque: a spring of \c stiffness
/// and a damper of stiffness * damping_time towards the target, solved implicitly (a soft
/// constraint), its approach speed limited to max_velocity and its impulse to max_effort times
/// the sub-step. At rest a joint pressed by a load L stands stiffness / L off its target, up to
/// max_effort; a finger commanded past an object closes at most at max_velocity, touches, and
/// presses with stiffness times its remaining distance to the target, at most max_effort.
struct ActuatorDesc {
  double position = 0.0;       ///< initial value (rad or m), within [lower, upper]
  double lower = 0.0;          ///< joint limits (rad or m), enforced as unilateral constraints
  double upper = 0.0;          ///< (lower <= upper)
  double inertia = 1e-4;       ///< kg m^2 (or kg): the joint's inertia including the rotor's
  double max_effort = 1.0;     ///< N m (or N): the largest torque the servo gives, > 0
  double max_velocity = 1.0;   ///< rad/s (or m/s): the servo's speed limit, > 0
  double stiffness = 20.0;     ///< N m/rad (or N/m): the servo's position gain, > 0
  double damping_time = 0.01;  ///< s: the servo's damping is stiffness * damping_time, >= 0
};

/// A joint carrying a kinematic body, as World::set_body_joints() takes it: moving actuator
/// \c actuator by dq moves the body by a rotation of gear * dq about the world line through
/// \c origin along \c axis (revolute) or a translation of gear * dq along \c axis (prismatic).
struct BodyJoint {
  int actuator = -1;
  Vec3 axis = Vec3::UnitZ();   ///< unit, world
  Vec3 origin = Vec3::Zero();  ///< a point on the axis, world (m)
  double gear = 1.0;           ///< d(joint value) / d(actuator value), e.g. a mimic multiplier
  bool prismatic = false;
};

/// The most joints that carry one body: the length of a chain from the hand frame (or an arm's
/// base) to a link.
inline constexpr int k_max_body_joints = 16;

namespace detail {

/// The state of an actuator in a World.
template <class S>
struct Actuator {
  S q = S(0), qd = S(0);  ///< position (rad or m) and velocity
  S q0 = S(0);            ///< position at the start of the step
  S target = S(0);        ///< servo target
  S lower = S(0), upper = S(0);
  S inertia = S(1), inv_inertia = S(1);
  S max_effort = S(1);  ///< the current torque limit of the servo
  S max_velocity = S(1);
  S stiffness = S(20), damping = S(0.2);  ///< servo spring (N m/rad) and damper (N m s/rad)
  S force = S(0);                         ///< external generalised force (N m), e.g. link weights
  S motor_impulse = S(0);                 ///< of the current sub-step, warm-started (N m s)
  S lower_impulse = S(0), upper_impulse = S(0);  ///< limit impulses, warm-started
  S step_impulse = S(0);                         ///< the motor's impulse summed over the last step
};

/// The joints that carry one kinematic body; count 0 for a body that no actuator moves.
template <class S>
struct BodyJoints {
  int count = 0;
  std::array<int, k_max_body_joints> actuator{};
  std::array<Vec<3, S>, k_max_body_joints> axis{}, origin{};
  std::array<S, k_max_body_joints> gear{};
  std::array<bool, k_max_body_joints> prismatic{};

  /// The velocity of the body's point \p p per unit velocity of joint j's actuator.
  [[nodiscard]] Vec<3, S> lever(int j, const Vec<3, S>& p) const noexcept {
    const auto u = static_cast<std::size_t>(j);
    return prismatic[u] ? Vec<3, S>(gear[u] * axis[u])
                        : Vec<3, S>(gear[u] * axis[u].cross(p - origin[u]));
  }
  /// The angular velocity of the body per unit velocity of joint j's actuator.
  [[nodiscard]] Vec<3, S> spin(int j) const noexcept {
    const auto u = static_cast<std::size_t>(j);
    return prismatic[u] ? Vec<3, S>::Zero() : Vec<3, S>(gear[u] * axis[u]);
  }
};

/// The inverse effective mass, in joint space, of a row whose Jacobian entries for the joints of
/// \p joints are \p s (s[j] = lever(j) . direction): sum over actuators of (the sum of s over the
/// joints that actuator drives)^2 / inertia. Joints of one actuator (a mimic pair in one chain)
/// add before squaring.
template <class S>
[[nodiscard]] S joint_space_k(const BodyJoints<S>& joints, std::span<const Actuator<S>> act,
                              const std::array<S, k_max_body_joints>& s1,
                              const std::array<S, k_max_body_joints>& s2) noexcept {
  S k = S(0);
  for (int i = 0; i < joints.count; ++i)
    for (int j = 0; j < joints.count; ++j) {
      const auto ui = static_cast<std::size_t>(i), uj = static_cast<std::size_t>(j);
      if (joints.actuator[ui] == joints.actuator[uj])
        k += s1[ui] * s2[uj] * act[static_cast<std::size_t>(joints.actuator[ui])].inv_inertia;
    }
  return k;
}

/// Applies the impulse \p P (N s, world), received at point \p p of the body that \p joints
/// carry, to its actuators: qd += inv_inertia * lever . P.
template <class S>
void push_joints(const BodyJoints<S>& joints, std::span<Actuator<S>> act, const Vec<3, S>& p,
                 const Vec<3, S>& P) noexcept {
  for (int j = 0; j < joints.count; ++j) {
    Actuator<S>& a = act[static_cast<std::size_t>(joints.actuator[static_cast<std::size_t>(j)])];
    a.qd += a.inv_inertia * joints.lever(j, p).dot(P);
  }
}

/// Applies the angular impulse \p L (N m s, world) received by the body to its actuators.
template <class S>
void twist_joints(const BodyJoints<S>& joints, std::span<Actuator<S>> act,
                  const Vec<3, S>& L) noexcept {
  for (int j = 0; j < joints.count; ++j) {
    Actuator<S>& a = act[static_cast<std::size_t>(joints.actuator[static_cast<std::size_t>(j)])];
    a.qd += a.inv_inertia * joints.spin(j).dot(L);
  }
}

/// The velocity of point \p p of the body due to its joints (world, m/s).
template <class S>
[[nodiscard]] Vec<3, S> joint_velocity(const BodyJoints<S>& joints,
                                       std::span<const Actuator<S>> act,
                                       const Vec<3, S>& p) noexcept {
  Vec<3, S> v = Vec<3, S>::Zero();
  for (int j = 0; j < joints.count; ++j)
    v += joints.lever(j, p) *
         act[static_cast<std::size_t>(joints.actuator[static_cast<std::size_t>(j)])].qd;
  return v;
}

/// The displacement of point \p p of the body due to its joints since the step began (m).
template <class S>
[[nodiscard]] Vec<3, S> joint_displacement(const BodyJoints<S>& joints,
                                           std::span<const Actuator<S>> act,
                                           const Vec<3, S>& p) noexcept {
  Vec<3, S> d = Vec<3, S>::Zero();
  for (int j = 0; j < joints.count; ++j) {
    const Actuator<S>& a =
        act[static_cast<std::size_t>(joints.actuator[static_cast<std::size_t>(j)])];
    d += joints.lever(j, p) * (a.q - a.q0);
  }
  return d;
}

/// The angular velocity of the body due to its joints (world, rad/s).
template <class S>
[[nodiscard]] Vec<3, S> joint_spin(const BodyJoints<S>& joints,
                                   std::span<const Actuator<S>> act) noexcept {
  Vec<3, S> w = Vec<3, S>::Zero();
  for (int j = 0; j < joints.count; ++j)
    w += joints.spin(j) *
         act[static_cast<std::size_t>(joints.actuator[static_cast<std::size_t>(j)])].qd;
  return w;
}

/// Which of a sub-step's two solves of the actuator and contact rows: with the position bias that
/// pushes overlaps apart and joints back within their limits (before positions are integrated),
/// or without it (the relax pass after).
enum class SolvePass : bool { biased, relax };

/// Every sub-step, before the contacts: applies the warm-started motor and limit impulses.
template <class S>
void warm_start_actuators(std::span<Actuator<S>> act) noexcept {
  for (Actuator<S>& a : act)
    a.qd += a.inv_inertia * (a.motor_impulse + a.lower_impulse - a.upper_impulse);
}

/// Every sub-step, twice (with the position bias of the limits, then without): the servo row
/// (velocity towards the commanded one, impulse within +-max_effort h) and the two limit rows.
/// A limit is speculative while the joint is short of it (it may close the gap within the
/// sub-step, no more) and rigid past it: a joint-space row has one degree of freedom and a known
/// inertia, so it needs no softness; the overshoot is removed at k_limit_baumgarte of it per
/// sub-step (at most max_push). A soft limit, as rigid contacts are (their stiffness scaled by
/// the effective mass), would let a strong servo on a light joint press far past it.
template <class S>
void solve_actuators(std::span<Actuator<S>> act, S h, SolvePass pass, S max_push) noexcept {
  const bool use_bias = pass == SolvePass::biased;
  constexpr S k_limit_baumgarte = S(0.2);
  const S inv_h = S(1) / h;
  for (Actuator<S>& a : act) {
    // Servo: a soft constraint C = q - target with a physical spring and damper (Catto, "Soft
    // constraints", GDC 2011: gamma = 1 / (h (c + h k)), bias rate k / (c + h k)), the bias
    // limited to the speed limit, the accumulated impulse to the torque limit. The spring is
    // the servo's own, so it acts in the relax pass too.
    const S k = a.stiffness, c = a.damping;
    const S gamma = S(1) / (h * (c + h * k));
    const S mass_scale = S(1) / (S(1) + a.inertia * gamma);
    const S impulse_scale = a.inertia * gamma * mass_scale;
    const S pull =
        detail::clamp<S>(k / (c + h * k) * (a.q - a.target), -a.max_velocity, a.max_velocity);
    const S limit = a.max_effort * h;
    const S next = detail::clamp<S>(
        a.motor_impulse - a.inertia * mass_scale * (a.qd + pull) - impulse_scale * a.motor_impulse,
        -limit, limit);
    a.qd += a.inv_inertia * (next - a.motor_impulse);
    a.motor_impulse = next;
    // Limits: C = q - lower >= 0 and C = upper - q >= 0.
    for (int side = 0; side < 2; ++side) {
      const S C = side == 0 ? a.q - a.lower : a.upper - a.q;
      const S v = side == 0 ? a.qd : -a.qd;
      S& accumulated = side == 0 ? a.lower_impulse : a.upper_impulse;
      S bias = S(0);
      if (C > S(0))
        bias = C * inv_h;
      else if (use_bias)
        bias = std::max(k_limit_baumgarte * C * inv_h, -max_push);
      const S total = std::max(accumulated - a.inertia * (v + bias), S(0));
      const S d = total - accumulated;
      accumulated = total;
      a.qd += side == 0 ? a.inv_inertia * d : -a.inv_inertia * d;
    }
  }
}

}  // namespace detail
}  // namespace topograsp
