// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Undoing a failed step of a World (internal): the bodies' and actuators' state saved at the
/// step's start, the check that ends a run (a non-finite, too fast or too far dynamic body or
/// actuator), and the restore.
#pragma once

#include <cmath>
#include <span>

#include <topograsp/core/eigen.hpp>
#include <topograsp/physics/actuator.hpp>
#include <topograsp/physics/collider.hpp>
#include <topograsp/physics/detail/math.hpp>
#include <topograsp/physics/rigid_body.hpp>

namespace topograsp::detail {

/// The state of one body at the start of a step.
template <class S>
struct SavedBody {
  Vec<3, S> x = Vec<3, S>::Zero(), v = Vec<3, S>::Zero(), w = Vec<3, S>::Zero();
  Quat<S> q = Quat<S>::Identity();
  Mat<3, 3, S> R = Mat<3, 3, S>::Identity();
};

/// Saves \p bodies into \p saved and \p actuators into \p saved_actuators (one each).
template <class S>
void save_state(std::span<const RigidBody<S>> bodies, std::span<const Actuator<S>> actuators,
                std::span<SavedBody<S>> saved, std::span<Actuator<S>> saved_actuators) noexcept {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    const RigidBody<S>& b = bodies[i];
    saved[i] = {b.x, b.v, b.w, b.q, b.R};
  }
  for (std::size_t i = 0; i < actuators.size(); ++i) saved_actuators[i] = actuators[i];
}

/// Puts \p bodies and \p actuators back as save_state() saved them, with their shapes (of
/// \p colliders).
template <class S>
void restore_state(std::span<RigidBody<S>> bodies, std::span<Actuator<S>> actuators,
                   std::span<const SavedBody<S>> saved,
                   std::span<const Actuator<S>> saved_actuators,
                   std::span<Collider<S>> colliders) noexcept {
  for (std::size_t i = 0; i < bodies.size(); ++i) {
    RigidBody<S>& b = bodies[i];
    b.x = saved[i].x;
    b.v = saved[i].v;
    b.w = saved[i].w;
    b.q = saved[i].q;
    b.R = b.q.toRotationMatrix();
    b.update_world_inertia();
    place_colliders(b, colliders);
  }
  for (std::size_t i = 0; i < actuators.size(); ++i) actuators[i] = saved_actuators[i];
}

/// False if a dynamic body is not finite, moves faster than \p max_speed or lies beyond
/// \p max_length, or an actuator is not finite or moves faster than \p max_speed.
template <class S>
[[nodiscard]] bool state_ok(std::span<const RigidBody<S>> bodies,
                            std::span<const Actuator<S>> actuators, S max_speed,
                            S max_length) noexcept {
  for (const RigidBody<S>& b : bodies) {
    if (b.type != BodyType::dynamic) continue;
    if (!b.x.allFinite() || !b.v.allFinite() || !b.w.allFinite() || !b.q.coeffs().allFinite())
      return false;
    if (b.v.norm() > max_speed || b.w.norm() > max_speed) return false;
    if (b.x.cwiseAbs().maxCoeff() > max_length) return false;
  }
  for (const Actuator<S>& a : actuators)
    if (!std::isfinite(a.q) || !std::isfinite(a.qd) || std::abs(a.qd) > max_speed) return false;
  return true;
}

}  // namespace topograsp::detail
