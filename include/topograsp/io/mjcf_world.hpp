// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// MJCF export of a physics World with its hand frozen, so a grasp can be re-checked in MuJoCo
/// (2.2 or later); the articulated export of a hand scene is io/mjcf.hpp.
#pragma once

#include <iomanip>
#include <ostream>
#include <string>
#include <string_view>

#include <Eigen/Geometry>

#include <topograsp/io/detail/mjcf_write.hpp>
#include <topograsp/physics/world.hpp>

namespace topograsp {

/// Writes \p world as an MJCF model that MuJoCo 2.2 loads: fixed bodies as geoms of the world
/// body; every kinematic body's shapes as geoms of one body named "hand" with mocap="true",
/// placed at \p hand_frame (the hand at its current configuration); each dynamic body as a body
/// with a free joint, named "object" (then "object_1", ...), with its geoms, mass, centre of mass
/// and full inertia. Options: the time step, gravity, an elliptic (circular) friction cone and
/// the Euler integrator. Each geom carries its body's friction coefficient mu and, with
/// torsional friction (condim 4), mu * torsional_friction_radius: MuJoCo takes the larger value
/// of a pair where topograsp takes sqrt(mu_a mu_b), the same when both bodies have the same mu.
/// MuJoCo's contacts use its own softness (solref, solimp defaults), not kinematic_stiffness.
template <class S>
void write_mjcf(std::ostream& os, const World<S>& world, const Eigen::Isometry3d& hand_frame,
                std::string_view model_name = "topograsp_scene") {
  const auto flags = os.flags();
  const auto precision = os.precision();
  os << std::setprecision(12);  // 1e-12 relative: far below any tolerance of a simulation
  const StepperOptions& o = world.options();
  const auto g = world.gravity().template cast<double>();
  const double torsion = o.torsional_friction_radius;
  os << "<mujoco model=\"" << model_name << "\">\n";
  os << "  <compiler angle=\"radian\"/>\n";
  os << "  <option timestep=\"" << o.time_step << "\" gravity=\"" << g.x() << ' ' << g.y() << ' '
     << g.z() << "\" cone=\"elliptic\" integrator=\"Euler\"/>\n";
  os << "  <worldbody>\n";
  const auto shape_pose = [&](const Collider<S>& c) {
    return world.body(c.body).pose() * c.spec.pose.isometry();
  };
  for (int b = 0; b < world.body_count(); ++b) {
    const RigidBody<S>& body = world.body(b);
    if (body.type != BodyType::fixed) continue;
    for (int c = body.first_collider; c < body.first_collider + body.n_colliders; ++c)
      detail::write_mjcf_geom(os, "    ", "fixed_" + std::to_string(c), world.collider(c).spec,
                              shape_pose(world.collider(c)), static_cast<double>(body.friction),
                              0.0);
  }
  os << "    <body name=\"hand\" mocap=\"true\"";
  detail::write_mjcf_pose(os, hand_frame);
  os << ">\n";
  const Eigen::Isometry3d hand_inv = hand_frame.inverse();
  for (int b = 0; b < world.body_count(); ++b) {
    const RigidBody<S>& body = world.body(b);
    if (body.type != BodyType::kinematic) continue;
    for (int c = body.first_collider; c < body.first_collider + body.n_colliders; ++c)
      detail::write_mjcf_geom(os, "      ", "hand_" + std::to_string(c), world.collider(c).spec,
                              hand_inv * shape_pose(world.collider(c)),
                              static_cast<double>(body.friction), torsion);
  }
  os << "    </body>\n";
  int n_objects = 0;
  for (int b = 0; b < world.body_count(); ++b) {
    const RigidBody<S>& body = world.body(b);
    if (body.type != BodyType::dynamic) continue;
    const std::string name = n_objects == 0 ? "object" : "object_" + std::to_string(n_objects);
    ++n_objects;
    os << "    <body name=\"" << name << '"';
    detail::write_mjcf_pose(os, body.pose());
    os << ">\n";
    os << "      <joint name=\"" << name << "_free\" type=\"free\"/>\n";
    const Mat3 I = body.inertia.template cast<double>();
    const Vec3 c = body.local_com.template cast<double>();
    os << "      <inertial pos=\"" << c.x() << ' ' << c.y() << ' ' << c.z() << "\" mass=\""
       << static_cast<double>(body.mass) << "\" fullinertia=\"" << I(0, 0) << ' ' << I(1, 1) << ' '
       << I(2, 2) << ' ' << I(0, 1) << ' ' << I(0, 2) << ' ' << I(1, 2) << "\"/>\n";
    for (int k = body.first_collider; k < body.first_collider + body.n_colliders; ++k)
      detail::write_mjcf_geom(os, "      ", name + "_" + std::to_string(k - body.first_collider),
                              world.collider(k).spec, world.collider(k).spec.pose.isometry(),
                              static_cast<double>(body.friction), torsion);
    os << "    </body>\n";
  }
  os << "  </worldbody>\n</mujoco>\n";
  os.flags(flags);
  os.precision(precision);
}

}  // namespace topograsp
