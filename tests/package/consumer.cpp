// SPDX-License-Identifier: BSD-3-Clause
// A downstream program: the SDH's fingertips at home must be 0.246 m above the palm.
#include <cmath>
#include <cstdio>
#include <topograsp/topograsp.hpp>

int main() {
  using namespace topograsp;
  KinematicsData<models::schunk_sdh> data;
  forward_kinematics(data, Vec<models::schunk_sdh.nq>::Zero());
  const double z = data.frame_p[static_cast<std::size_t>(models::schunk_sdh.frame("tip_1"))].z();
  std::printf("SDH fingertip height at home: %.4f m\n", z);
  return std::abs(z - 0.246) < 1e-9 ? 0 : 1;
}
