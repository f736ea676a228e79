// SPDX-License-Identifier: BSD-3-Clause
// A downstream program: the SDH's fingertips at home must be 0.246 m above the palm, and a hand
// imported from its MJCF file by topograsp_import_hand() is a model with its 10 joints.
#include <cmath>
#include <cstdio>
#include <topograsp/topograsp.hpp>

#include "consumer_hand.hpp"

inline constexpr auto imported = topograsp::make_model(
    "imported", consumer_hand::links, consumer_hand::shapes, consumer_hand::frames);
static_assert(imported.n_links == 11 && imported.nq == 9);  // 10 joints, one coupled

int main() {
  using namespace topograsp;
  KinematicsData<models::schunk_sdh> data;
  forward_kinematics(data, Vec<models::schunk_sdh.nq>::Zero());
  const double z = data.frame_p[static_cast<std::size_t>(models::schunk_sdh.frame("tip_1"))].z();
  std::printf("SDH fingertip height at home: %.4f m\n", z);
  return std::abs(z - 0.246) < 1e-9 ? 0 : 1;
}
