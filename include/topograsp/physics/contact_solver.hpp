// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The contact solver in stages, as Box2D v3 splits its solver: prepare_contacts() once a step,
/// then every sub-step warm_start_contacts(), solve_contacts() with the soft bias, (positions
/// integrated, physics/detail/step.hpp) and solve_contacts() without it (relax),
/// accumulate_impulses(); at the end of the step store_impulses(). Free functions over the
/// manifolds of a World and its step context (StepContext); World::step() sequences them. None
/// allocates. Internal (topograsp::detail): the manifolds and bodies they take are the World's own,
/// whose invariants TOPOGRASP_ASSERT checks.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>

#include <topograsp/core/assert.hpp>
#include <topograsp/core/constants.hpp>
#include <topograsp/geometry/detail/closest.hpp>
#include <topograsp/physics/actuator.hpp>
#include <topograsp/physics/contact.hpp>
#include <topograsp/physics/detail/step.hpp>
#include <topograsp/physics/rigid_body.hpp>
#include <topograsp/physics/stepper_options.hpp>

namespace topograsp::detail {

/// Stage 1, once a step, after the narrow phase: for every touching manifold, the anchors (world
/// and body axes), the normal and tangent effective masses, the tangent basis, the softness of
/// each point (rigid soft contact, b2MakeSoft, or the hand's physical spring-damper) and the
/// torsional friction row; friction impulses carried from the last step are projected onto the
/// new tangent basis (warm starting).
template <class S>
void prepare_contacts(std::span<Manifold<S>> manifolds, const StepContext<S>& ctx) noexcept {
  const std::span<const RigidBody<S>> bodies = ctx.bodies;
  const std::span<const BodyJoints<S>> joints = ctx.joints;
  const std::span<const Actuator<S>> act = ctx.actuators;
  const StepperOptions& options = ctx.options;
  const S h = ctx.h;
  using V3 = Vec<3, S>;
  using M3 = Mat<3, 3, S>;
  // Rigid soft contacts: b2MakeSoft. With omega = 2 pi f: a1 = 2 zeta + h omega,
  // a2 = h omega a1, a3 = 1 / (1 + a2); bias rate omega / a1, mass scale a2 a3, impulse scale a3.
  const S pi_s = static_cast<S>(pi);
  const S hertz = std::min(static_cast<S>(options.contact_hertz), S(0.25) / h);
  const S omega = S(2) * pi_s * hertz, zeta = static_cast<S>(options.contact_damping_ratio);
  const S a1 = S(2) * zeta + h * omega, a2 = h * omega * a1, a3 = S(1) / (S(1) + a2);
  const S rigid_bias = omega / a1, rigid_mass = a2 * a3, rigid_impulse = a3;
  const S k_kinematic = static_cast<S>(options.kinematic_stiffness);
  const S zeta_kinematic = static_cast<S>(options.kinematic_damping_ratio);
  const S torsion = static_cast<S>(options.torsional_friction_radius);
  for (Manifold<S>& m : manifolds) {
    if (m.count == 0) continue;
    TOPOGRASP_ASSERT(m.body_a >= 0 && m.body_b >= 0 &&
                         static_cast<std::size_t>(m.body_a) < bodies.size() &&
                         static_cast<std::size_t>(m.body_b) < bodies.size(),
                     "a manifold's bodies are in the world");
    const RigidBody<S>& A = bodies[static_cast<std::size_t>(m.body_a)];
    const RigidBody<S>& B = bodies[static_cast<std::size_t>(m.body_b)];
    const S mA = A.inv_mass, mB = B.inv_mass;
    const M3& iA = A.inv_inertia;
    const M3& iB = B.inv_inertia;
    // A body carried by joint-space actuators adds their inverse inertia along each row.
    const BodyJoints<S>& JA = joints[static_cast<std::size_t>(m.body_a)];
    const BodyJoints<S>& JB = joints[static_cast<std::size_t>(m.body_b)];
    m.articulated = JA.count > 0 ? -1 : JB.count > 0 ? 1 : 0;
    const BodyJoints<S>& J = m.articulated < 0 ? JA : JB;
    V3 axis = V3::Zero();
    for (int k = 0; k < m.count; ++k) {
      ContactPoint<S>& c = m.points[static_cast<std::size_t>(k)];
      const V3& n = c.normal;
      axis += n;
      c.anchor_a = c.point - A.x;
      c.anchor_b = c.point - B.x;
      c.local_a = A.R.transpose() * c.anchor_a;
      c.local_b = B.R.transpose() * c.anchor_b;
      const V3 rnA = c.anchor_a.cross(n), rnB = c.anchor_b.cross(n);
      S kn = mA + mB + rnA.dot(iA * rnA) + rnB.dot(iB * rnB);
      detail::tangent_basis<S>(n, c.t1, c.t2);
      const V3 a1v = c.anchor_a.cross(c.t1), a2v = c.anchor_a.cross(c.t2);
      const V3 b1v = c.anchor_b.cross(c.t1), b2v = c.anchor_b.cross(c.t2);
      Eigen::Matrix<S, 2, 2> K;
      K(0, 0) = mA + mB + a1v.dot(iA * a1v) + b1v.dot(iB * b1v);
      K(1, 1) = mA + mB + a2v.dot(iA * a2v) + b2v.dot(iB * b2v);
      K(0, 1) = a1v.dot(iA * a2v) + b1v.dot(iB * b2v);
      if (m.articulated != 0) {
        std::array<S, k_max_body_joints> sn{}, s1{}, s2{};
        for (int j = 0; j < J.count; ++j) {
          const V3 l = J.lever(j, c.point);
          const auto u = static_cast<std::size_t>(j);
          sn[u] = l.dot(n);
          s1[u] = l.dot(c.t1);
          s2[u] = l.dot(c.t2);
        }
        kn += joint_space_k<S>(J, act, sn, sn);
        K(0, 0) += joint_space_k<S>(J, act, s1, s1);
        K(1, 1) += joint_space_k<S>(J, act, s2, s2);
        K(0, 1) += joint_space_k<S>(J, act, s1, s2);
      }
      K(1, 0) = K(0, 1);
      c.normal_mass = kn > S(0) ? S(1) / kn : S(0);
      const S det = K.determinant();
      c.tangent_mass =
          det > S(0) ? Eigen::Matrix<S, 2, 2>(K.inverse()) : Eigen::Matrix<S, 2, 2>::Zero();
      c.tangent_mass_iso = K.trace() > S(0) ? S(2) / K.trace() : S(0);
      c.tangent_impulse =
          Eigen::Matrix<S, 2, 1>(c.friction_impulse.dot(c.t1), c.friction_impulse.dot(c.t2));
      c.step_impulse = S(0);
      c.ra = c.anchor_a;
      c.rb = c.anchor_b;
      c.n_now = n;
      c.t1_now = c.t1;
      c.t2_now = c.t2;
      if (m.kinematic && k_kinematic > S(0)) {
        // Physical spring-damper (Catto, "Soft constraints", GDC 2011): with stiffness k and
        // damping c = 2 zeta sqrt(k m_eff), gamma = 1 / (h (c + h k)) and bias rate
        // k / (c + h k); at rest the accumulated impulse per sub-step is k d h, a force k d.
        const S kp = k_kinematic / static_cast<S>(m.count);
        const S meff = c.normal_mass;
        const S damping = S(2) * zeta_kinematic * std::sqrt(kp * meff);
        const S gamma = S(1) / (h * (damping + h * kp));
        c.bias_rate = kp / (damping + h * kp);
        c.mass_scale = S(1) / (S(1) + meff * gamma);
        c.impulse_scale = meff * gamma * c.mass_scale;
        c.max_push = static_cast<S>(options.kinematic_push_max_speed);
      } else {
        c.bias_rate = rigid_bias;
        c.mass_scale = rigid_mass;
        c.impulse_scale = rigid_impulse;
        c.max_push = static_cast<S>(options.contact_push_max_speed);
      }
    }
    m.twist_mass = S(0);
    if (m.kinematic && torsion > S(0) && axis.squaredNorm() > S(1e-12)) {
      m.twist_axis = axis.normalized();
      m.twist_axis_now = m.twist_axis;
      S kt = m.twist_axis.dot(iA * m.twist_axis) + m.twist_axis.dot(iB * m.twist_axis);
      if (m.articulated != 0) {
        std::array<S, k_max_body_joints> st{};
        for (int j = 0; j < J.count; ++j)
          st[static_cast<std::size_t>(j)] = J.spin(j).dot(m.twist_axis);
        kt += joint_space_k<S>(J, act, st, st);
      }
      if (kt > S(0)) m.twist_mass = S(1) / kt;
    }
    if (m.twist_mass == S(0)) m.twist_impulse = S(0);
  }
}

/// Applies the impulse \p impulse (N s, world) at the offset \p r from the centre of mass of \p b;
/// only dynamic bodies move.
template <class S>
void apply_impulse(RigidBody<S>& b, const Vec<3, S>& impulse, const Vec<3, S>& r) noexcept {
  if (b.type != BodyType::dynamic) return;
  b.v += b.inv_mass * impulse;
  b.w += b.inv_inertia * r.cross(impulse);
}

/// Stage 2, every sub-step: applies the accumulated impulses of every point (normal and friction
/// along the turned frame) and of the torsional row.
template <class S>
void warm_start_contacts(std::span<Manifold<S>> manifolds, const StepContext<S>& ctx) noexcept {
  const std::span<RigidBody<S>> bodies = ctx.bodies;
  const std::span<const BodyJoints<S>> joints = ctx.joints;
  const std::span<Actuator<S>> act = ctx.actuators;
  using V3 = Vec<3, S>;
  for (Manifold<S>& m : manifolds) {
    if (m.count == 0) continue;
    RigidBody<S>& A = bodies[static_cast<std::size_t>(m.body_a)];
    RigidBody<S>& B = bodies[static_cast<std::size_t>(m.body_b)];
    const S sigma = static_cast<S>(m.articulated);
    const BodyJoints<S>& J =
        joints[static_cast<std::size_t>(m.articulated < 0 ? m.body_a : m.body_b)];
    for (int k = 0; k < m.count; ++k) {
      const ContactPoint<S>& c = m.points[static_cast<std::size_t>(k)];
      const V3 P = c.normal_impulse * c.n_now + c.tangent_impulse.x() * c.t1_now +
                   c.tangent_impulse.y() * c.t2_now;
      apply_impulse<S>(A, -P, c.ra);
      apply_impulse<S>(B, P, c.rb);
      if (m.articulated != 0) push_joints<S>(J, act, c.point, V3(sigma * P));
    }
    if (m.twist_mass > S(0)) {
      const V3 L = m.twist_impulse * m.twist_axis_now;
      if (A.type == BodyType::dynamic) A.w -= A.inv_inertia * L;
      if (B.type == BodyType::dynamic) B.w += B.inv_inertia * L;
      if (m.articulated != 0) twist_joints<S>(J, act, V3(sigma * L));
    }
  }
}

/// Stage 3, twice every sub-step (with the soft position bias before integrating positions, without
/// it after, the "relax" pass): sequential impulses on every manifold, normal rows first, then
/// friction in a circular cone, then torsional friction.
/// The contact frame turns with body A (ctx.turned: each body's rotation since the step began),
/// the anchors with their bodies; overlaps are pushed apart only in the biased pass.
template <class S>
void solve_contacts(std::span<Manifold<S>> manifolds, const StepContext<S>& ctx,
                    SolvePass pass) noexcept {
  const std::span<RigidBody<S>> bodies = ctx.bodies;
  const std::span<const BodyJoints<S>> joints = ctx.joints;
  const std::span<Actuator<S>> act = ctx.actuators;
  const std::span<const Mat<3, 3, S>> turned = ctx.turned;
  const bool use_bias = pass == SolvePass::biased;
  TOPOGRASP_ASSERT(turned.size() == bodies.size(), "one rotation per body");
  using V3 = Vec<3, S>;
  using M3 = Mat<3, 3, S>;
  const S inv_h = ctx.inv_h;
  for (Manifold<S>& m : manifolds) {
    if (m.count == 0) continue;
    RigidBody<S>& A = bodies[static_cast<std::size_t>(m.body_a)];
    RigidBody<S>& B = bodies[static_cast<std::size_t>(m.body_b)];
    // The contact frame turns with body A, and the anchors with their bodies, so that a grasp
    // turning by several degrees a step keeps consistent contact velocities.
    const M3& dR = turned[static_cast<std::size_t>(m.body_a)];
    const S mu = m.friction;
    // Velocities in registers; inverse masses are zero for kinematic and fixed bodies.
    V3 vA = A.v, wA = A.w, vB = B.v, wB = B.w;
    const S mA = A.inv_mass, mB = B.inv_mass;
    const M3& iA = A.inv_inertia;
    const M3& iB = B.inv_inertia;
    // A body carried by actuators (sigma -1 for A, +1 for B) moves with their velocities too.
    const S sigma = static_cast<S>(m.articulated);
    const BodyJoints<S>& J =
        joints[static_cast<std::size_t>(m.articulated < 0 ? m.body_a : m.body_b)];
    const std::span<const Actuator<S>> cact = act;
    const auto push = [&](const ContactPoint<S>& c, const V3& P) {
      vA -= mA * P;
      wA -= iA * c.ra.cross(P);
      vB += mB * P;
      wB += iB * c.rb.cross(P);
      if (m.articulated != 0) push_joints<S>(J, act, c.point, V3(sigma * P));
    };
    const auto relative_velocity = [&](const ContactPoint<S>& c) {
      V3 dv = vB + wB.cross(c.rb) - vA - wA.cross(c.ra);
      if (m.articulated != 0) dv += sigma * joint_velocity<S>(J, cact, c.point);
      return dv;
    };
    S total = S(0);
    for (int k = 0; k < m.count; ++k) {
      ContactPoint<S>& c = m.points[static_cast<std::size_t>(k)];
      c.ra = A.R * c.local_a;
      c.rb = B.R * c.local_b;
      c.n_now = dR * c.normal;
      // Current separation: the two anchors started at the same point, so their gap along the
      // (turned) normal adds to the separation found by the narrow phase.
      S s = (B.x + c.rb - A.x - c.ra).dot(c.n_now) + c.separation;
      if (m.articulated != 0) s += sigma * joint_displacement<S>(J, cact, c.point).dot(c.n_now);
      S bias = S(0), mass_scale = S(1), impulse_scale = S(0);
      if (s > S(0)) {
        bias = s * inv_h;  // speculative: allow the gap to close, no more
      } else if (use_bias) {
        bias = std::max(c.bias_rate * s, -c.max_push);
        mass_scale = c.mass_scale;
        impulse_scale = c.impulse_scale;
      }
      const S vn = relative_velocity(c).dot(c.n_now);
      const S impulse =
          -c.normal_mass * mass_scale * (vn + bias) - impulse_scale * c.normal_impulse;
      const S next = std::max(c.normal_impulse + impulse, S(0));
      const S d = next - c.normal_impulse;
      c.normal_impulse = next;
      total += next;
      push(c, V3(d * c.n_now));
    }
    // Friction after the normal impulses, limited by them (the order of Box2D v3: with soft
    // contacts, the biased solve lowers the normal impulse that the relax pass restores).
    for (int k = 0; k < m.count; ++k) {
      ContactPoint<S>& c = m.points[static_cast<std::size_t>(k)];
      c.t1_now = dR * c.t1;
      c.t2_now = dR * c.t2;
      const V3 dv = relative_velocity(c);
      const Eigen::Matrix<S, 2, 1> vt(dv.dot(c.t1_now), dv.dot(c.t2_now));
      Eigen::Matrix<S, 2, 1> next = c.tangent_impulse - c.tangent_mass * vt;
      // Circular cone: |friction| <= mu * normal. Sticking uses the full 2x2 effective mass;
      // when sliding, its off-diagonal coupling would turn the impulse away from the slip, so
      // the direction comes from an isotropic mass and the length from the cone.
      const S limit = mu * c.normal_impulse;
      if (next.squaredNorm() > limit * limit) {
        next = c.tangent_impulse - c.tangent_mass_iso * vt;
        const S len = next.norm();
        next *= len > S(0) ? limit / len : S(0);
      }
      const Eigen::Matrix<S, 2, 1> d = next - c.tangent_impulse;
      c.tangent_impulse = next;
      push(c, V3(d.x() * c.t1_now + d.y() * c.t2_now));
    }
    if (m.twist_mass > S(0)) {
      // Torsional friction: |torque impulse| <= mu * radius * normal impulse.
      m.twist_axis_now = dR * m.twist_axis;
      const S limit = mu * static_cast<S>(ctx.options.torsional_friction_radius) * total;
      S wn = (wB - wA).dot(m.twist_axis_now);
      if (m.articulated != 0) wn += sigma * joint_spin<S>(J, cact).dot(m.twist_axis_now);
      const S next = detail::clamp<S>(m.twist_impulse - m.twist_mass * wn, -limit, limit);
      const S d = next - m.twist_impulse;
      m.twist_impulse = next;
      const V3 L = d * m.twist_axis_now;
      wA -= iA * L;
      wB += iB * L;
      if (m.articulated != 0) twist_joints<S>(J, act, V3(sigma * L));
    }
    if (A.type == BodyType::dynamic) {
      A.v = vA;
      A.w = wA;
    }
    if (B.type == BodyType::dynamic) {
      B.v = vB;
      B.w = wB;
    }
  }
}

/// Stage 4a, after each sub-step: adds the sub-step's normal impulses to the step totals
/// (ContactPoint::step_impulse, what World::normal_impulse() reports).
template <class S>
void accumulate_impulses(std::span<Manifold<S>> manifolds) noexcept {
  for (Manifold<S>& m : manifolds)
    for (int k = 0; k < m.count; ++k)
      m.points[static_cast<std::size_t>(k)].step_impulse +=
          m.points[static_cast<std::size_t>(k)].normal_impulse;
}

/// Stage 4b, at the end of a step: stores each point's friction impulse in world axes, which the
/// next step's contact matching and prepare_contacts() carry over (warm starting).
template <class S>
void store_impulses(std::span<Manifold<S>> manifolds) noexcept {
  for (Manifold<S>& m : manifolds)
    for (int k = 0; k < m.count; ++k) {
      ContactPoint<S>& c = m.points[static_cast<std::size_t>(k)];
      c.friction_impulse = c.tangent_impulse.x() * c.t1_now + c.tangent_impulse.y() * c.t2_now;
    }
}

}  // namespace topograsp::detail
