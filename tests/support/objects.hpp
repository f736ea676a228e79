// SPDX-License-Identifier: BSD-3-Clause
// Objects made of primitives for tests and benchmarks: a bottle and a hammer, as the paper's
// experiments use, and blocks whose distances are exact.
#pragma once

#include <topograsp/geometry/composite.hpp>

namespace topograsp::test {

/// A 0.5 l bottle standing on the origin: a body cylinder, a shoulder and a neck.
inline Composite bottle(const Eigen::Isometry3d& pose = Eigen::Isometry3d::Identity()) {
  Eigen::Isometry3d body = Eigen::Isometry3d::Identity(), neck = body;
  body.translation() = Vec3(0, 0, 0.08);
  neck.translation() = Vec3(0, 0, 0.19);
  return Composite({Primitive::cylinder(body, 0.035, 0.08),
                    Primitive::sphere(Vec3(0, 0, 0.16), 0.03),
                    Primitive::cylinder(neck, 0.013, 0.03)})
      .transformed(pose);
}

/// A claw hammer lying along x: a wooden handle (cylinder about x) and a steel head (box).
inline Composite hammer(const Eigen::Isometry3d& pose = Eigen::Isometry3d::Identity()) {
  Eigen::Isometry3d handle = Eigen::Isometry3d::Identity(), head = handle;
  handle.linear() = Eigen::AngleAxisd(1.5707963267948966, Vec3::UnitY()).toRotationMatrix();
  handle.translation() = Vec3(0.0, 0, 0);
  head.translation() = Vec3(0.16, 0, 0);
  return Composite({Primitive::cylinder(handle, 0.015, 0.15),
                    Primitive::box(head, Vec3(0.015, 0.06, 0.0125))})
      .transformed(pose);
}

/// An object of the shapes whose distances are exact: a sphere, a capsule and a box.
inline Composite blocks(const Eigen::Isometry3d& pose = Eigen::Isometry3d::Identity()) {
  Eigen::Isometry3d b = Eigen::Isometry3d::Identity();
  b.translation() = Vec3(0.0, 0.04, 0.0);
  return Composite({Primitive::sphere(Vec3(0.03, 0, 0), 0.03),
                    Primitive::capsule(Vec3(-0.05, -0.03, 0), Vec3(0.05, -0.03, 0.02), 0.015),
                    Primitive::box(b, Vec3(0.03, 0.015, 0.04))})
      .transformed(pose);
}

}  // namespace topograsp::test
