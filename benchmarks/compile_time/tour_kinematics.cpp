// SPDX-License-Identifier: BSD-3-Clause
// Compile-time benchmark (benchmarks/compile_time.sh): the README tour's first snippet, the SDH's
// kinematics through the umbrella header, as a user's first program would write it.
#include <cstdio>

#include <topograsp/topograsp.hpp>

int main() {
  using namespace topograsp;
  KinematicsData<models::schunk_sdh> data;
  Vec<7> q;
  q << 0, 0, 1.0472, 0, 1.0472, 0, 1.0472;
  require_configuration<models::schunk_sdh>(q);
  forward_kinematics(data, q);
  const int tip = models::schunk_sdh.frame("tip_1");
  const Vec3 p = data.frame_p[tip];
  const Mat<6, 7> J = frame_jacobian(data, tip);
  std::printf("%.3f %.3f %.3f %.3f\n", p.x(), p.y(), p.z(), J.norm());
}
