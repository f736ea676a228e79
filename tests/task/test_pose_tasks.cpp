// SPDX-License-Identifier: BSD-3-Clause
#include <random>

#include <catch2/catch.hpp>

#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/task/axis_task.hpp>
#include <topograsp/task/joint_limit_task.hpp>
#include <topograsp/task/line_task.hpp>
#include <topograsp/task/orientation_task.hpp>
#include <topograsp/task/position_task.hpp>
#include <topograsp/task/posture_task.hpp>

#include "support/finite_diff.hpp"
#include "support/random.hpp"

using namespace topograsp;

namespace {

template <const auto& M>
void check_pose_jacobians(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  for (int trial = 0; trial < 5; ++trial) {
    const Vec<M.nq> q = test::random_configuration<M>(rng);
    for (int f = 0; f < static_cast<int>(M.frames.size()); ++f) {
      INFO(M.name.view() << " frame " << M.frames[static_cast<std::size_t>(f)].spec.name.view()
                         << " trial " << trial);
      const Vec3 offset(0.1 * g(rng), 0.1 * g(rng), 0.1 * g(rng));
      CHECK(test::jacobian_error(PositionTask<M>(f, offset), q) < 1e-7);
      CHECK(test::jacobian_error(AxisTask<M>(f, Vec3(g(rng), g(rng), g(rng))), q) < 1e-7);
      CHECK(test::jacobian_error(OrientationTask<M>(f), q) < 1e-7);
      const Vec3 c(g(rng), g(rng), g(rng)), a(g(rng), g(rng), g(rng));
      CHECK(test::jacobian_error(LineTask<M>(f, c, a, offset), q) < 1e-7);
    }
    Vec<M.nq> w;
    for (int i = 0; i < M.nq; ++i) w[i] = std::abs(g(rng));
    CHECK(test::jacobian_error(PostureTask<M>(w), q) < 1e-7);
  }
}

template <const auto& M>
void check_limit_jacobian(std::uint32_t seed) {
  std::mt19937 rng(seed);
  const Vec<M.nq> lo = lower_limits<M>(), hi = upper_limits<M>();
  const double margin = 0.1 * (hi - lo).minCoeff();
  const JointLimitTask<M> task(margin);
  int active = 0;
  for (int trial = 0; trial < 20; ++trial) {
    Vec<M.nq> q;
    for (int i = 0; i < M.nq; ++i) {
      const double span = hi[i] - lo[i];
      q[i] = std::uniform_real_distribution<double>(lo[i] - 0.2 * span, hi[i] + 0.2 * span)(rng);
    }
    INFO(M.name.view() << " trial " << trial);
    CHECK(test::jacobian_error(task, q) < 1e-7);
    KinematicsData<M> d;
    forward_kinematics(d, q);
    const Vec<M.nq> phi = task.value(d);
    for (int i = 0; i < M.nq; ++i) {
      if (q[i] < lo[i] + margin)
        CHECK(phi[i] == Approx(q[i] - lo[i] - margin));
      else if (q[i] > hi[i] - margin)
        CHECK(phi[i] == Approx(q[i] - hi[i] + margin));
      else
        CHECK(phi[i] == 0.0);
      if (phi[i] != 0.0) ++active;
    }
  }
  CHECK(active > 0);
}

}  // namespace

TEST_CASE("pose and posture task Jacobians match central differences on every model",
          "[task][pose]") {
  check_pose_jacobians<models::schunk_sdh>(21);
  check_pose_jacobians<models::human_hand>(22);
  check_pose_jacobians<models::barrett_bh8>(23);
  check_pose_jacobians<models::schunk_arm>(24);
  check_pose_jacobians<models::schunk_arm_sdh>(25);
  check_pose_jacobians<models::schunk_sdh_free>(26);
  check_pose_jacobians<models::human_hand_free>(27);
  check_pose_jacobians<models::barrett_bh8_free>(28);
}

TEST_CASE("joint limit penalties are zero inside and measure the excess outside",
          "[task][limits]") {
  check_limit_jacobian<models::schunk_sdh>(31);
  check_limit_jacobian<models::human_hand>(32);
  check_limit_jacobian<models::barrett_bh8>(33);
  check_limit_jacobian<models::schunk_arm>(34);
  check_limit_jacobian<models::schunk_arm_sdh>(35);
  check_limit_jacobian<models::schunk_sdh_free>(36);
  check_limit_jacobian<models::human_hand_free>(37);
  check_limit_jacobian<models::barrett_bh8_free>(38);
}

TEST_CASE("pose tasks report what they measure", "[task][pose]") {
  constexpr auto& M = models::schunk_arm_sdh;
  KinematicsData<M> d;
  std::mt19937 rng(3);
  forward_kinematics(d, test::random_configuration<M>(rng));
  const int tip = M.frame("thumb_tip");
  const auto f = static_cast<std::size_t>(tip);
  CHECK((PositionTask<M>("thumb_tip").value(d) - d.frame_p[f]).norm() == 0.0);
  CHECK(
      (PositionTask<M>(tip, Vec3(0, 0, 0.1)).value(d) - (d.frame_p[f] + 0.1 * d.frame_R[f].col(2)))
          .norm() < 1e-15);
  CHECK((AxisTask<M>("thumb_tip", Vec3(0, 0, 2)).value(d) - d.frame_R[f].col(2)).norm() < 1e-15);
  CHECK((OrientationTask<M>(tip).value(d) - orientation_target(d.frame_R[f])).norm() == 0.0);
  // Cost of the orientation task: |R - R*|_F^2 = 4 (1 - cos theta).
  const Mat3 Rs =
      d.frame_R[f] * Eigen::AngleAxisd(0.3, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  CHECK((OrientationTask<M>(tip).value(d) - orientation_target(Rs)).squaredNorm() ==
        Approx(4.0 * (1.0 - std::cos(0.3))));
  const PostureTask<M> posture;
  const Vec<14> qc = Vec<14>::Constant(0.2);
  CHECK((posture.value(d) - posture.target(qc)).norm() == Approx((d.q - qc).norm()));
}

TEST_CASE("the line task is the offset of a point from a line", "[task][pose]") {
  constexpr auto& M = models::schunk_arm_sdh;
  KinematicsData<M> d;
  std::mt19937 rng(5);
  forward_kinematics(d, test::random_configuration<M>(rng));
  const auto f = static_cast<std::size_t>(M.frame("grasp_centre"));
  const Vec3 x = d.frame_p[f];
  const Vec3 a = Vec3(1, -2, 0.5).normalized();
  // On the line, wherever along it: zero.
  for (const double s : {-0.3, 0.0, 0.7})
    CHECK(LineTask<M>("grasp_centre", x + s * a, 3.0 * a).value(d).norm() < 1e-15);
  // Off it: the distance, whatever the point on the line and the length of the direction.
  const Vec3 across = a.unitOrthogonal().cross(a).normalized();
  const LineTask<M> line("grasp_centre", x - 0.05 * across + 0.2 * a, 0.1 * a);
  CHECK(line.value(d).norm() == Approx(0.05));
  // The basis is orthonormal and orthogonal to the direction.
  CHECK((line.basis() * line.basis().transpose() - Mat<2, 2>::Identity()).norm() < 1e-15);
  CHECK((line.basis() * a).norm() < 1e-15);
  // The offset point of the frame.
  const Vec3 o(0.0, 0.0, 0.02);
  const Vec3 xo = x + d.frame_R[f] * o;
  CHECK(LineTask<M>("grasp_centre", xo, a, o).value(d).norm() < 1e-15);
}

TEST_CASE("pose tasks reject bad input naming the argument", "[task][pose]") {
  constexpr auto& M = models::schunk_sdh;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(PositionTask<M>("nowhere"), Catch::StartsWith("frame"));
  CHECK_THROWS_WITH(PositionTask<M>(99), Catch::StartsWith("frame"));
  CHECK_THROWS_WITH(PositionTask<M>("tip_1", Vec3(nan, 0, 0)), Catch::StartsWith("offset"));
  CHECK_THROWS_WITH(AxisTask<M>("tip_1", Vec3::Zero()), Catch::StartsWith("axis"));
  CHECK_THROWS_WITH(AxisTask<M>(-1, Vec3::UnitZ()), Catch::StartsWith("frame"));
  CHECK_THROWS_WITH(OrientationTask<M>("x"), Catch::StartsWith("frame"));
  const Vec3 z = Vec3::UnitZ(), o = Vec3::Zero();
  CHECK_THROWS_WITH(LineTask<M>("x", o, z), Catch::StartsWith("frame"));
  CHECK_THROWS_WITH(LineTask<M>("tip_1", Vec3(nan, 0, 0), z), Catch::StartsWith("point"));
  CHECK_THROWS_WITH(LineTask<M>("tip_1", o, o), Catch::StartsWith("direction"));
  CHECK_THROWS_WITH(LineTask<M>("tip_1", o, Vec3(0, nan, 1)), Catch::StartsWith("direction"));
  CHECK_THROWS_WITH(LineTask<M>("tip_1", o, z, Vec3(0, 0, nan)), Catch::StartsWith("offset"));
  CHECK_THROWS_WITH(JointLimitTask<M>(-0.1), Catch::StartsWith("margin"));
  CHECK_THROWS_WITH(JointLimitTask<M>(10.0), Catch::StartsWith("margin"));
  Vec<7> w = Vec<7>::Ones();
  w[2] = -1.0;
  CHECK_THROWS_WITH(PostureTask<M>(w), Catch::StartsWith("weights"));
  w[2] = nan;
  CHECK_THROWS_AS(PostureTask<M>(w), invalid_argument);
}
