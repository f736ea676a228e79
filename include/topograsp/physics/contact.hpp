// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// ContactPoint and Manifold: the contacts between one pair of shapes and the solver's state for
/// them (accumulated impulses for warm starting, effective masses, softness), and
/// match_contacts(), which carries impulses from one step's points to the next's.
#pragma once

#include <array>
#include <cstdint>

#include <topograsp/geometry/detail/closest.hpp>
#include <topograsp/physics/contact_set.hpp>

namespace topograsp {

/// One contact point and its solver state.
template <class S = double>
struct ContactPoint {
  using V3 = Vec<3, S>;
  V3 point = V3::Zero();    ///< world point midway between the surfaces at the step's start (m)
  V3 normal = V3::UnitZ();  ///< unit, from body A into body B
  S separation = S(0);      ///< at the step's start (m); negative when overlapping
  std::uint32_t id = 0;     ///< feature id used to match points between steps (warm starting)
  /// Total normal impulse over the last step (N s): divide by the time step for the force.
  S step_impulse = S(0);
  /// Accumulated normal impulse of the current sub-step (N s), warm-started.
  S normal_impulse = S(0);
  Eigen::Matrix<S, 2, 1> tangent_impulse = Eigen::Matrix<S, 2, 1>::Zero();  ///< along t1, t2
  V3 friction_impulse = V3::Zero();  ///< tangent_impulse in world axes, carried between steps

  // Solver data, set up at the start of each step.
  V3 anchor_a = V3::Zero(), anchor_b = V3::Zero();  ///< from each centre of mass (world)
  V3 local_a = V3::Zero(), local_b = V3::Zero();    ///< the same in body axes
  V3 t1 = V3::UnitX(), t2 = V3::UnitY();            ///< tangent basis
  S normal_mass = S(0);
  Eigen::Matrix<S, 2, 2> tangent_mass = Eigen::Matrix<S, 2, 2>::Zero();
  S tangent_mass_iso = S(0);  ///< 2 / trace of the tangent effective-mass inverse
  S bias_rate = S(0), mass_scale = S(1), impulse_scale = S(0), max_push = S(0);
  // Within a step: the anchors turned with their bodies, the normal and tangents with body A.
  V3 ra = V3::Zero(), rb = V3::Zero();
  V3 n_now = V3::UnitZ(), t1_now = V3::UnitX(), t2_now = V3::UnitY();
};

/// The contacts of one pair of shapes (a "manifold"), at most 4 points, and the pair's torsional
/// friction row.
template <class S = double>
struct Manifold {
  int body_a = -1, body_b = -1;          ///< body indices in the World
  int collider_a = -1, collider_b = -1;  ///< shape indices in the World
  int count = 0;                         ///< points in use
  std::array<ContactPoint<S>, 4> points{};
  S friction = S(0);       ///< the pair's Coulomb coefficient
  bool kinematic = false;  ///< one body is kinematic: physical stiffness, torsional friction
  /// Which body joint-space actuators carry (World::set_body_joints()): -1 body A, +1 body B,
  /// 0 neither; set each step by prepare_contacts().
  int articulated = 0;
  Vec<3, S> twist_axis = Vec<3, S>::UnitZ();
  S twist_mass = S(0);     ///< 0 when the pair has no torsional friction this step
  S twist_impulse = S(0);  ///< accumulated torsional impulse (N m s)
  Vec<3, S> twist_axis_now = Vec<3, S>::UnitZ();  ///< turned with A
};

/// Replaces the points of \p m by the narrow phase's \p found, each starting from the impulses of
/// the previous point with the same feature id (warm starting) or from zero; a manifold left
/// without points drops its torsional impulse.
template <class S>
void match_contacts(Manifold<S>& m, const ContactSet<S>& found) noexcept {
  // Keep the previous points' impulses for warm starting.
  const int old_count = m.count;
  std::array<std::uint32_t, 4> old_id{};
  std::array<S, 4> old_normal{};
  std::array<Vec<3, S>, 4> old_friction{};
  for (int k = 0; k < old_count; ++k) {
    const auto u = static_cast<std::size_t>(k);
    old_id[u] = m.points[u].id;
    old_normal[u] = m.points[u].normal_impulse;
    old_friction[u] = m.points[u].friction_impulse;
  }
  m.count = found.count;
  if (found.count == 0) m.twist_impulse = S(0);
  for (int k = 0; k < found.count; ++k) {
    const auto u = static_cast<std::size_t>(k);
    ContactPoint<S>& c = m.points[u];
    const ContactFeature<S>& f = found.points[u];
    c.point = f.point;
    c.normal = f.normal;
    c.separation = f.separation;
    c.id = f.id;
    c.normal_impulse = S(0);
    c.friction_impulse.setZero();
    for (int o = 0; o < old_count; ++o)
      if (old_id[static_cast<std::size_t>(o)] == f.id) {
        c.normal_impulse = old_normal[static_cast<std::size_t>(o)];
        c.friction_impulse = old_friction[static_cast<std::size_t>(o)];
        break;
      }
  }
}

}  // namespace topograsp
