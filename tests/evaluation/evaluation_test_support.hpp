// SPDX-License-Identifier: BSD-3-Clause
// Scenes shared by the evaluation tests. (EIGEN_RUNTIME_NO_MALLOC, for the no-allocation test, is
// defined for every test executable by tests/CMakeLists.txt.)
#pragma once

#include <topograsp/evaluation.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/physics.hpp>

namespace topograsp::test {

/// An isometry from a rotation taking z to \p axis and a translation.
inline Eigen::Isometry3d z_along(const Eigen::Vector3d& axis, const Eigen::Vector3d& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() =
      Eigen::Quaterniond::FromTwoVectors(Eigen::Vector3d::UnitZ(), axis).toRotationMatrix();
  T.translation() = p;
  return T;
}

/// A cylinder object (radius r, half height hh, mass m) with its axis along \p axis of the hand
/// frame, centred at \p centre (hand frame), for a hand at \p hand.
inline ObjectSpec cylinder_object(const Eigen::Isometry3d& hand, const Eigen::Vector3d& centre,
                                  const Eigen::Vector3d& axis, double r, double hh, double m) {
  ObjectSpec o;
  o.shapes = {cylinder("", Pose{}, r, hh)};
  o.pose = to_pose(hand * z_along(axis, centre));
  o.mass = m;
  return o;
}

/// The SDH's side grasp of a 0.5 kg bottle (radius 35 mm, height 0.2 m): the hand horizontal
/// (fingers along world +x), the bottle upright between the fingers and the thumb.
inline Eigen::Isometry3d sdh_side_pose() {
  Eigen::Isometry3d hand = Eigen::Isometry3d::Identity();
  hand.linear() << 0, 0, 1, 1, 0, 0, 0, 1, 0;  // hand z -> world x, hand y -> world z
  hand.translation() = Eigen::Vector3d(0.0, 0.0, 0.3);
  return hand;
}

inline HandScene<models::schunk_sdh> sdh_bottle_scene(double friction = 1.0,
                                                      double pad_stiffness = 8000.0) {
  const Eigen::Isometry3d hand = sdh_side_pose();
  HandSceneOptions so;
  so.friction = friction;
  so.stepper.kinematic_stiffness = pad_stiffness;
  Vec<7> q;
  q << 0.0, -0.6, 0.3, -0.6, 0.3, -0.6, 0.3;
  return HandScene<models::schunk_sdh>(
      hand, q,
      cylinder_object(hand, Eigen::Vector3d(0, 0, 0.15), Eigen::Vector3d::UnitY(), 0.035, 0.1, 0.5),
      so);
}

}  // namespace topograsp::test
