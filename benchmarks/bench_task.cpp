// SPDX-License-Identifier: BSD-3-Clause
// Micro-benchmarks of the task layer: winding numbers of the human hand's curves, the collision
// potential of the human hand against a bottle and a hammer, the whole transfer task set of the
// 14-DOF arm + SDH. Each evaluates one configuration from a fixed pool (forward kinematics is
// timed separately where it is not part of the measured call).
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include <topograsp/geometry.hpp>
#include <topograsp/kinematics.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/task.hpp>

#include "support/objects.hpp"

namespace {

using namespace topograsp;

template <const auto& M>
std::vector<Vec<M.nq>> configurations(std::size_t n, double closing) {
  std::mt19937 rng(1);
  std::vector<Vec<M.nq>> out;
  for (std::size_t k = 0; k < n; ++k) {
    Vec<M.nq> q;
    for (int i = 0; i < M.nq; ++i) {
      const LinkSpec& s = M.joint_spec(i);
      const double mid =
          0.5 * (s.lower + s.upper) + closing * s.closing * 0.25 * (s.upper - s.lower);
      q[i] = mid + std::uniform_real_distribution<double>(-0.1, 0.1)(rng);
    }
    out.push_back(clamp_to_limits<M>(q));
  }
  return out;
}

using test::bottle;
using test::hammer;

constexpr auto& k_hand = models::human_hand;
constexpr auto& k_robot = models::schunk_arm_sdh;

// The object held in front of the human palm (+x), its axis along the fingers for the bottle and
// across them for the hammer's handle.
Eigen::Isometry3d in_human_hand(bool across) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.translation() = Vec3(0.045, 0.0, across ? 0.09 : 0.02);
  if (across) T.linear() = Eigen::AngleAxisd(pi / 2, Vec3::UnitZ()).toRotationMatrix();
  return T;
}

void BM_human_hand_fk(benchmark::State& state) {
  const auto qs = configurations<k_hand>(64, 1.0);
  KinematicsData<k_hand> d;
  std::size_t k = 0;
  for (auto _ : state) {
    forward_kinematics(d, qs[k++ & 63]);
    benchmark::DoNotOptimize(d.p.data());
  }
}
BENCHMARK(BM_human_hand_fk);

void BM_winding_human_hand_value(benchmark::State& state) {
  const auto qs = configurations<k_hand>(64, 1.0);
  std::vector<KinematicsData<k_hand>> ds(64);
  for (std::size_t k = 0; k < 64; ++k) forward_kinematics(ds[k], qs[k]);
  const WindingTask<k_hand> task(Vec3(0.045, 0.0, 0.11));
  std::size_t k = 0;
  for (auto _ : state) benchmark::DoNotOptimize(task.value(ds[k++ & 63]));
}
BENCHMARK(BM_winding_human_hand_value);

void BM_winding_human_hand_jacobian(benchmark::State& state) {
  const auto qs = configurations<k_hand>(64, 1.0);
  std::vector<KinematicsData<k_hand>> ds(64);
  for (std::size_t k = 0; k < 64; ++k) forward_kinematics(ds[k], qs[k]);
  const WindingTask<k_hand> task(Vec3(0.045, 0.0, 0.11));
  Vec<4> phi;
  Mat<4, 20> J;
  std::size_t k = 0;
  for (auto _ : state) {
    task.evaluate(ds[k++ & 63], phi, J);
    benchmark::DoNotOptimize(J.data());
  }
}
BENCHMARK(BM_winding_human_hand_jacobian);

void collision_bench(benchmark::State& state, const Composite& object, bool jacobian) {
  const auto qs = configurations<k_hand>(64, 1.0);
  std::vector<KinematicsData<k_hand>> ds(64);
  for (std::size_t k = 0; k < 64; ++k) forward_kinematics(ds[k], qs[k]);
  const CollisionTask<k_hand> task(object, 0.02);
  double active = 0.0;
  for (const auto& d : ds) active += task.value(d)[0] > 0.0 ? 1.0 : 0.0;
  Vec<1> phi;
  Mat<1, 20> J;
  std::size_t k = 0;
  for (auto _ : state) {
    if (jacobian) {
      task.evaluate(ds[k++ & 63], phi, J);
      benchmark::DoNotOptimize(J.data());
    } else {
      benchmark::DoNotOptimize(task.value(ds[k++ & 63]));
    }
  }
  state.counters["in_margin_fraction"] = active / 64.0;
}

void BM_collision_human_hand_bottle_value(benchmark::State& state) {
  collision_bench(state, bottle(in_human_hand(false)), false);
}
void BM_collision_human_hand_bottle_jacobian(benchmark::State& state) {
  collision_bench(state, bottle(in_human_hand(false)), true);
}
void BM_collision_human_hand_hammer_value(benchmark::State& state) {
  collision_bench(state, hammer(in_human_hand(true)), false);
}
void BM_collision_human_hand_hammer_jacobian(benchmark::State& state) {
  collision_bench(state, hammer(in_human_hand(true)), true);
}
BENCHMARK(BM_collision_human_hand_bottle_value);
BENCHMARK(BM_collision_human_hand_bottle_jacobian);
BENCHMARK(BM_collision_human_hand_hammer_value);
BENCHMARK(BM_collision_human_hand_hammer_jacobian);

// The paper's transfer problem on the 14-DOF robot: forward kinematics, then the whitened
// residual and Jacobian of two windings, collision with the bottle, approach axis, joint limits
// and posture (what AICO evaluates per time step).
void BM_transfer_task_set_schunk_arm_sdh(benchmark::State& state) {
  const auto qs = configurations<k_robot>(64, 0.5);
  KinematicsData<k_robot> d;
  forward_kinematics(d, qs[0]);
  const Vec3 centre = d.frame_p[static_cast<std::size_t>(k_robot.frame("grasp_centre"))];
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.translation() = centre - Vec3(0, 0, 0.1);
  auto set = make_task_set(
      scheduled(WindingTask<k_robot>(centre), interpolated_target<2>(Vec2::Zero(), Vec2(0.4, 0.35)),
                precision(1e1, 1e3)),
      scheduled(CollisionTask<k_robot>(bottle(pose), 0.02), constant_target(Vec<1>(0.0)),
                constant_precision(1e2)),
      scheduled(AxisTask<k_robot>("palm_centre", Vec3::UnitZ()), constant_target(Vec3(0, 0, -1)),
                precision(0.0, 1e2)),
      scheduled(JointLimitTask<k_robot>(0.05), constant_target(Vec<14>(Vec<14>::Zero())),
                constant_precision(1e3)),
      scheduled(PostureTask<k_robot>(), constant_target(Vec<14>(qs[0])), constant_precision(1e-2)));
  using Set = decltype(set);
  Vec<Set::dim> e;
  Mat<Set::dim, 14> J;
  std::size_t k = 0;
  int t = 0;
  for (auto _ : state) {
    forward_kinematics(d, qs[k++ & 63]);
    set.residual(d, t, 100, e, J);
    t = (t + 1) % 101;
    benchmark::DoNotOptimize(J.data());
  }
}
BENCHMARK(BM_transfer_task_set_schunk_arm_sdh);

}  // namespace

BENCHMARK_MAIN();
