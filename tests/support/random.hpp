// SPDX-License-Identifier: BSD-3-Clause
// Seeded random configurations inside a model's joint limits, for tests.
#pragma once

#include <random>

#include <topograsp/kinematics/data.hpp>

namespace topograsp::test {

/// A configuration drawn uniformly inside the limits of M (free-base ranges are narrowed to +-1).
template <const auto& M>
Vec<M.nq> random_configuration(std::mt19937_64& rng) {
  Vec<M.nq> q;
  for (int i = 0; i < M.nq; ++i) {
    const LinkSpec& s = M.joint_spec(i);
    const double lo = s.lower < -1.0 ? -1.0 : s.lower;
    const double hi = s.upper > 1.0 && s.lower < -1.0 ? 1.0 : s.upper;
    q[i] = std::uniform_real_distribution<double>(lo, hi)(rng);
  }
  return q;
}

}  // namespace topograsp::test
