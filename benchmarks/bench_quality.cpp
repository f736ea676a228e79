// SPDX-License-Identifier: BSD-3-Clause
// Micro-benchmarks of grasp quality: the contact wrenches of a four-finger grasp (Eigen only) and,
// where qhull was found, its Ferrari-Canny epsilon (Q1) with 8 and 16 cone edges. There is no peer
// to compare against here (GraspIt's QualEpsilon needs its whole simulator).
#include <vector>

#include <benchmark/benchmark.h>

#include <topograsp/evaluation/grasp_wrench.hpp>
#ifdef TOPOGRASP_HAVE_QHULL
#include <topograsp/evaluation/grasp_quality.hpp>
#endif

namespace {

using namespace topograsp;

// Four fingertips on a 10 cm cube (centre at the origin), friction 0.5: a thumb on the +x face
// against three fingers, one on each of the -x, +y and -y faces, not at the faces' centres.
std::vector<ContactForQuality> four_finger_grasp() {
  const double a = 0.05;
  return {{{a, 0.005, 0.01}, -Vec3::UnitX(), 0.5},
          {{-a, -0.01, 0.0}, Vec3::UnitX(), 0.5},
          {{0.01, a, -0.015}, -Vec3::UnitY(), 0.5},
          {{-0.005, -a, 0.02}, Vec3::UnitY(), 0.5}};
}

void BM_contact_wrenches_4(benchmark::State& state) {
  const auto c = four_finger_grasp();
  QualityOptions o;
  o.edges = static_cast<int>(state.range(0));
  Eigen::Matrix<double, 6, Eigen::Dynamic> w;
  for (auto _ : state) {
    contact_wrenches(c, Vec3::Zero(), 0.0866, o, w);
    benchmark::DoNotOptimize(w.data());
  }
}
BENCHMARK(BM_contact_wrenches_4)->Arg(8)->Arg(64);

#ifdef TOPOGRASP_HAVE_QHULL
void BM_ferrari_canny_epsilon_4(benchmark::State& state) {
  const auto c = four_finger_grasp();
  QualityOptions o;
  o.edges = static_cast<int>(state.range(0));
  double epsilon = 0.0;
  for (auto _ : state) {
    const GraspQuality q = ferrari_canny_epsilon(c, Vec3::Zero(), 0.0866, o);
    // The const overload: libbenchmark 1.7's DoNotOptimize on a mutable double ("+m,r") is
    // miscompiled by GCC 12 at -O3 (the counter below read garbage).
    benchmark::DoNotOptimize(q.epsilon);
    epsilon = q.epsilon;
  }
  state.counters["epsilon"] = epsilon;
}
// 8 edges (GraspIt's) and 16; 64 edges take seconds per call (docs/evaluation.md).
BENCHMARK(BM_ferrari_canny_epsilon_4)->Arg(8)->Arg(16)->Unit(benchmark::kMicrosecond);
#endif

}  // namespace

BENCHMARK_MAIN();
