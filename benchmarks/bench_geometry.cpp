// SPDX-License-Identifier: BSD-3-Clause
// signed_distance() on pairs with a cylinder (GJK apart, EPA overlapping): the narrow phase of the
// planner's collision task for the bottle and the can (task/collision_task.hpp). Each benchmark
// cycles through 256 random pairs of one kind (fixed seed), apart or overlapping; the time is per
// call. No peer: MuJoCo's narrow phase for a pair of shapes is not part of its public API (2.2).
#include <random>
#include <vector>

#include <benchmark/benchmark.h>

#include <topograsp/geometry.hpp>

#include "support/random.hpp"

using namespace topograsp;

namespace {

// A random shape of `type`, sizes 2 to 10 cm.
Primitive random_shape(std::mt19937& rng, ShapeType type, double spread) {
  std::uniform_real_distribution<double> s(0.02, 0.1);
  const Eigen::Isometry3d T = test::random_pose(rng, spread);
  if (type == ShapeType::capsule) {
    const Vec3 h = T.linear().col(2) * s(rng);
    return Primitive::capsule(T.translation() - h, T.translation() + h, 0.5 * s(rng));
  }
  if (type == ShapeType::box) return Primitive::box(T, Vec3(s(rng), s(rng), s(rng)));
  return Primitive::cylinder(T, s(rng), s(rng));
}

// 256 pairs (a shape of `other`, a cylinder) that overlap (or, if !overlapping, are apart).
std::vector<std::pair<Primitive, Primitive>> cylinder_pairs(ShapeType other, bool overlapping) {
  std::mt19937 rng(7);
  std::vector<std::pair<Primitive, Primitive>> out;
  while (out.size() < 256) {
    const Primitive a = random_shape(rng, other, 0.1),
                    b = random_shape(rng, ShapeType::cylinder, 0.1);
    if ((signed_distance(a, b).distance < 0.0) == overlapping) out.emplace_back(a, b);
  }
  return out;
}

void run_pairs(benchmark::State& state, ShapeType other, bool overlapping) {
  const auto pairs = cylinder_pairs(other, overlapping);
  std::size_t k = 0;
  for (auto _ : state) {
    const auto& [a, b] = pairs[k++ % pairs.size()];
    benchmark::DoNotOptimize(signed_distance(a, b));
  }
}

void BM_signed_distance_capsule_cylinder_overlapping(benchmark::State& state) {
  run_pairs(state, ShapeType::capsule, true);
}
void BM_signed_distance_box_cylinder_overlapping(benchmark::State& state) {
  run_pairs(state, ShapeType::box, true);
}
void BM_signed_distance_cylinder_cylinder_overlapping(benchmark::State& state) {
  run_pairs(state, ShapeType::cylinder, true);
}
void BM_signed_distance_capsule_cylinder_apart(benchmark::State& state) {
  run_pairs(state, ShapeType::capsule, false);
}

}  // namespace

BENCHMARK(BM_signed_distance_capsule_cylinder_overlapping);
BENCHMARK(BM_signed_distance_box_cylinder_overlapping);
BENCHMARK(BM_signed_distance_cylinder_cylinder_overlapping);
BENCHMARK(BM_signed_distance_capsule_cylinder_apart);

BENCHMARK_MAIN();
