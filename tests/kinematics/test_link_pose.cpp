// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>

#include "support/random.hpp"

using namespace topograsp;

namespace {

// At random configurations of M: link_pose() of every link holds exactly the data's R and p (and
// a last row 0 0 0 1), and every frame's pose is its link's pose times the frame's offset.
template <const auto& M>
void check_link_poses() {
  std::mt19937_64 rng(7);
  KinematicsData<M> d;
  for (int trial = 0; trial < 10; ++trial) {
    forward_kinematics(d, test::random_configuration<M>(rng));
    for (std::size_t l = 0; l < M.n_links; ++l) {
      const Eigen::Isometry3d T = link_pose(d, static_cast<int>(l));
      CHECK(T.linear() == d.R[l]);
      CHECK(T.translation() == d.p[l]);
      CHECK(T.matrix().row(3) == Eigen::RowVector4d(0, 0, 0, 1));
    }
    for (std::size_t f = 0; f < M.n_frames; ++f) {
      const Eigen::Isometry3d expected =
          link_pose(d, M.frames[f].link) * M.frames[f].spec.offset.isometry();
      CHECK(frame_pose(d, static_cast<int>(f)).isApprox(expected, 1e-12));
    }
  }
}

}  // namespace

TEST_CASE("link_pose is the data's rotation and position of the link", "[kinematics][pose]") {
  SECTION("Schunk SDH") { check_link_poses<models::schunk_sdh>(); }
  SECTION("SDH on the arm") { check_link_poses<models::schunk_arm_sdh>(); }
  SECTION("human hand on a free base") { check_link_poses<models::human_hand_free>(); }
  SECTION("Barrett on a free base") { check_link_poses<models::barrett_bh8_free>(); }
}
