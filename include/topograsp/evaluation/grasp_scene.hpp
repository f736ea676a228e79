// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// GraspScene: what a stability test needs of a simulated grasp, so that the same tests run in
/// the built-in stepper (HandScene) and in MuJoCo (MujocoScene, io/mujoco when MuJoCo is linked).
#pragma once

#include <concepts>

#include <topograsp/core/eigen.hpp>
#include <topograsp/core/status.hpp>

namespace topograsp {

/// A hand holding an object in a simulator. The hand frame is placed by set_hand_pose() (the
/// next step() moves it there); its fingers are driven by their motors as the scene was set up.
/// Copying or copy-assigning a scene copies its whole state (stability_suite() assigns the
/// closing state to one working scene before each test); an assignment may reuse the target's
/// buffers.
template <class T>
concept GraspScene = std::copyable<T> && requires(T s, const T c, const Eigen::Isometry3d& pose,
                                                  const Vec3& g, double d) {
  { s.step() } -> std::same_as<Status>;          ///< one time step
  s.set_hand_pose(pose);                         ///< hand frame target (world)
  s.set_gravity(g);                              ///< m/s^2, world frame
  { c.gravity() } -> std::convertible_to<Vec3>;  ///< m/s^2, world frame
  { c.hand_pose() } -> std::convertible_to<Eigen::Isometry3d>;
  { c.object_in_hand() } -> std::convertible_to<Eigen::Isometry3d>;  ///< object in hand
  { c.object_com() } -> std::convertible_to<Vec3>;                   ///< world (m)
  { c.palm_centre() } -> std::convertible_to<Vec3>;                  ///< world (m)
  { c.hand_contacts(d) } -> std::convertible_to<int>;                ///< points within d (m)
  { c.hand_force() } -> std::convertible_to<double>;                 ///< total normal force (N)
  { c.deepest_penetration() } -> std::convertible_to<double>;        ///< m, >= 0
  { c.object_mass() } -> std::convertible_to<double>;                ///< kg
  { c.time_step() } -> std::convertible_to<double>;                  ///< s
};

}  // namespace topograsp
