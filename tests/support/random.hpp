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

}  // namespace topograsp::test
