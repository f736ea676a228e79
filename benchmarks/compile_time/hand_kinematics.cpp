// SPDX-License-Identifier: BSD-3-Clause
// Compile-time benchmark (benchmarks/compile_time.sh): one imported hand's kinematics and the
// winding of its hand curves around a point, through the narrow headers a user needs for that.
#include <array>
#include <cstdio>

#include <topograsp/kinematics.hpp>
#include <topograsp/model/models/allegro_hand.hpp>
#include <topograsp/task/hand_curve.hpp>
#include <topograsp/task/winding.hpp>

int main() {
  using namespace topograsp;
  constexpr auto& hand = models::allegro_hand;
  KinematicsData<hand> data;
  const Vec<hand.nq> q = Vec<hand.nq>::Constant(0.3);
  forward_kinematics(data, q);
  const Mat<6, hand.nq> J = frame_jacobian(data, hand.frame("palm_centre"));
  std::array<Vec3, static_cast<std::size_t>(hand_curve_capacity<hand>)> points;
  for (int c = 0; c < hand_curve_count<hand>; ++c) {
    const int n = hand_curve_points(data, c, points);
    std::printf("curve %d: winding %.3f\n", c,
                winding(std::span<const Vec3>(points.data(), static_cast<std::size_t>(n)),
                        Vec3(0.0, 0.0, 0.1)));
  }
  std::printf("%.3f\n", J.norm());
}
