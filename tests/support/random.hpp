// SPDX-License-Identifier: BSD-3-Clause
// Seeded random configurations inside a model's joint limits, for tests and benchmarks.
#pragma once

#include <algorithm>
#include <random>

#include <topograsp/kinematics/data.hpp>

namespace topograsp::test {

/// A configuration of M drawn uniformly inside its joint limits, one draw per entry in order, with
/// the ranges of prismatic joints (the free base's translations, +-10 m) narrowed to
/// +-\p prismatic_range (m; infinity: the full limits). \p rng is any standard engine.
template <const auto& M, class Rng>
Vec<M.nq> random_configuration(Rng& rng, double prismatic_range = 0.3) {
  Vec<M.nq> q;
  for (int i = 0; i < M.nq; ++i) {
    const LinkSpec& s = M.joint_spec(i);
    double lo = s.lower, hi = s.upper;
    if (s.type == JointType::prismatic) {
      lo = std::max(lo, -prismatic_range);
      hi = std::min(hi, prismatic_range);
    }
    std::uniform_real_distribution<double> u(lo, hi);
    q[i] = u(rng);
  }
  return q;
}

/// A pose within \p spread (m) of the origin along each axis, its rotation from a uniformly drawn
/// quaternion: four draws in [-1, 1] for the rotation, then three in [-spread, spread].
template <class Rng>
Eigen::Isometry3d random_pose(Rng& rng, double spread) {
  std::uniform_real_distribution<double> u(-spread, spread), a(-1.0, 1.0);
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::Quaterniond(a(rng), a(rng), a(rng), a(rng)).normalized().toRotationMatrix();
  T.translation() = Vec3(u(rng), u(rng), u(rng));
  return T;
}

}  // namespace topograsp::test
