// SPDX-License-Identifier: BSD-3-Clause
#include <random>

#include <catch2/catch.hpp>

#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/task.hpp>

#include "support/finite_diff.hpp"
#include "support/objects.hpp"
#include "support/random.hpp"

using namespace topograsp;

namespace {

constexpr auto& k_robot = models::schunk_arm_sdh;
using Data = KinematicsData<k_robot>;

// The paper's transfer problem on the 14-DOF robot: two windings, collision, approach axis,
// limits, posture.
auto transfer_set(const Vec3& centre, const Vec2& windings) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = centre - Vec3(0, 0, 0.1);
  return make_task_set(
      scheduled(WindingTask<k_robot>(centre), interpolated_target<2>(Vec2::Zero(), windings),
                precision(1e1, 1e3)),
      scheduled(CollisionTask<k_robot>(test::bottle(pose), 0.02), constant_target(Vec<1>(0.0)),
                constant_precision(1e2)),
      scheduled(AxisTask<k_robot>("palm_centre", Vec3::UnitZ()),
                constant_target(Vec3(Vec3(1, 0, -1).normalized())), precision(0.0, 1e2)),
      scheduled(JointLimitTask<k_robot>(0.05), constant_target(Vec<14>(Vec<14>::Zero())),
                constant_precision(1e3)),
      scheduled(PostureTask<k_robot>(), constant_target(Vec<14>(Vec<14>::Zero())),
                constant_precision(1e-2)));
}

}  // namespace

TEST_CASE("a task set stacks whitened residuals and Jacobians", "[task][set]") {
  std::mt19937 rng(9);
  Data d;
  const Vec<14> q0 = test::random_configuration<k_robot>(rng);
  forward_kinematics(d, q0);
  const Vec3 centre = d.frame_p[static_cast<std::size_t>(k_robot.frame("grasp_centre"))];
  auto set = transfer_set(centre, Vec2(0.4, 0.35));
  using Set = decltype(set);
  static_assert(TaskStack<Set>);
  static_assert(Set::dim == 2 + 1 + 3 + 14 + 14);
  static_assert(Set::offset<0> == 0 && Set::offset<1> == 2 && Set::offset<2> == 3 &&
                Set::offset<3> == 6 && Set::offset<4> == 20);
  set.start_from(d);
  CHECK(set.get<0>().target.start == set.get<0>().task.value(d));
  const int T = 10;
  for (int t : {0, 3, T}) {
    const Vec<14> q = test::random_configuration<k_robot>(rng);
    forward_kinematics(d, q);
    Vec<Set::dim> e;
    Mat<Set::dim, 14> J;
    set.residual(d, t, T, e, J);
    CHECK(e.squaredNorm() == Approx(set.cost(d, t, T)).epsilon(1e-12));
    const auto costs = set.task_costs(d, t, T);
    // Winding block: sqrt(rho) (w - y*(t)) with the interpolated target.
    const double rho = t == T ? 1e3 : 1e1;
    const Vec2 y = set.get<0>().target.at(t, T);
    CHECK((e.head<2>() - std::sqrt(rho) * (set.get<0>().task.value(d) - y)).norm() < 1e-12);
    CHECK(costs[0] == Approx(e.head<2>().squaredNorm()).epsilon(1e-12));
    // The approach axis only counts at the end.
    if (t < T) CHECK(e.segment<3>(3).isZero());
    if (t < T) CHECK(J.middleRows<3>(3).isZero());
    // J is the Jacobian of e (central differences).
    Mat<Set::dim, 14> Jn;
    for (int i = 0; i < 14; ++i) {
      Vec<14> qp = q, qm = q;
      qp[i] += 1e-6;
      qm[i] -= 1e-6;
      Vec<Set::dim> ep, em;
      Mat<Set::dim, 14> Jdummy;
      forward_kinematics(d, qp);
      set.residual(d, t, T, ep, Jdummy);
      forward_kinematics(d, qm);
      set.residual(d, t, T, em, Jdummy);
      Jn.col(i) = (ep - em) / 2e-6;
    }
    CHECK((J - Jn).cwiseAbs().maxCoeff() < 3e-3 * std::max(1.0, J.cwiseAbs().maxCoeff()));
  }
}

TEST_CASE("schedules interpolate targets and switch precisions at the end", "[task][set]") {
  const auto target = interpolated_target<2>(Vec2(0, 1), Vec2(1, 3));
  CHECK(target.at(0, 4) == Vec2(0, 1));
  CHECK(target.at(1, 4) == Vec2(0.25, 1.5));
  CHECK(target.at(4, 4) == Vec2(1, 3));
  CHECK(target.at(7, 4) == Vec2(1, 3));
  CHECK(target.at(0, 0) == Vec2(1, 3));
  const auto c = constant_target<2>(Vec2(5, 6));
  CHECK(c.at(0, 4) == Vec2(5, 6));
  CHECK(c.at(4, 4) == Vec2(5, 6));
  const PrecisionSchedule p = precision(1.0, 100.0);
  CHECK(p.at(0, 4) == 1.0);
  CHECK(p.at(3, 4) == 1.0);
  CHECK(p.at(4, 4) == 100.0);
  CHECK(constant_precision(2.0).at(4, 4) == 2.0);
}

TEST_CASE("schedules reject bad input naming the argument", "[task][set]") {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(constant_precision(-1.0), Catch::StartsWith("precision"));
  CHECK_THROWS_WITH(precision(1.0, nan), Catch::StartsWith("precision"));
  CHECK_THROWS_WITH(constant_target<2>(Vec2(nan, 0)), Catch::StartsWith("target"));
  CHECK_THROWS_WITH(interpolated_target<2>(Vec2(nan, 0), Vec2::Zero()), Catch::StartsWith("start"));
  CHECK_THROWS_WITH(interpolated_target<2>(Vec2::Zero(), Vec2(0, nan)), Catch::StartsWith("goal"));
}
