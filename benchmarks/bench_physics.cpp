// SPDX-License-Identifier: BSD-3-Clause
// Physics benchmarks: steps per second of the SDH holding a bottle, of the human hand holding a
// hammer (a demonstration of the default run) and of the human hand holding the YCB mustard bottle
// (a mesh object: its BADGr boxes are the convex pieces both engines collide), the same grasps
// articulated in MuJoCo 2.2 (when found; MujocoScene, the second judge) per scene step of 1/60 s,
// the ratio, and the time of one full stability suite; for the mesh object also what making it
// costs (reading, checks, mass properties, BADGr) and the planner's hand-object distance on its
// boxes beside the same query on the built-in bottle's cylinders.
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include <benchmark/benchmark.h>
#include <topograsp/evaluation.hpp>
#include <topograsp/grasp/human_grasps.hpp>
#include <topograsp/grasp/hypothesis.hpp>
#include <topograsp/grasp/object.hpp>
#include <topograsp/grasp/placement.hpp>
#include <topograsp/io/mjcf.hpp>
#include <topograsp/io/ycb_objects.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/physics.hpp>

#ifdef TOPOGRASP_HAVE_MUJOCO
#include <optional>

#include <topograsp/mujoco/mujoco_scene.hpp>
#endif

using namespace topograsp;

namespace {

// Steps per measured batch: each batch restarts from the grasp just closed, so both engines
// simulate the same 2 s of holding.
constexpr int batch = 120;

Eigen::Isometry3d frame(const Eigen::Matrix3d& R, const Eigen::Vector3d& p) {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  T.translation() = p;
  return T;
}

// A 0.5 l PET bottle: body r = 35 mm, 200 mm tall; neck r = 13 mm, 50 mm; 0.55 kg full.
HandScene<models::schunk_sdh> sdh_bottle() {
  Eigen::Matrix3d R;
  R << 0, 0, 1, 1, 0, 0, 0, 1, 0;  // fingers along world x, the bottle upright along hand y
  const Eigen::Isometry3d hand = frame(R, Eigen::Vector3d(0, 0, 0.3));
  ObjectSpec bottle;
  bottle.shapes = {cylinder("", Pose{}, 0.035, 0.1), cylinder("", at(0, 0, 0.125), 0.013, 0.025)};
  const Eigen::Isometry3d in_hand =
      frame(Eigen::AngleAxisd(-pi / 2, Eigen::Vector3d::UnitX()).toRotationMatrix(),
            Eigen::Vector3d(0, 0, 0.15));
  bottle.pose = to_pose(hand * in_hand);
  bottle.mass = 0.55;
  Vec<7> q;
  q << 0.0, -0.6, 0.3, -0.6, 0.3, -0.6, 0.3;
  HandScene<models::schunk_sdh> scene(hand, q, bottle);
  (void)close_hand(scene);
  return scene;
}

// A grasp of the default run's human hand that both engines judge stable: hypothesis 64 of the
// hammer (steel head, hickory handle, 0.61 kg), closed by close_human_grasp() as demonstrate()
// closes it.
constexpr int human_hypothesis = 64;

HandScene<models::human_hand> human_hammer() {
  const GraspObject hammer = objects::hammer();
  const auto closed =
      close_human_grasp(hammer, box_hypotheses(hammer)[static_cast<std::size_t>(human_hypothesis)]);
  if (!closed) {
    std::fprintf(stderr, "bench_physics: hypothesis %d of the hammer no longer reaches it\n",
                 human_hypothesis);
    std::exit(1);
  }
  return closed->scene;
}

// The YCB mustard bottle (data/objects/ycb) and the human hand closed on it from the first of its
// hypotheses whose demonstration is stable (seed 1, the built-in judge), as demonstrate() closes
// it.
const GraspObject& mustard() {
  static const GraspObject o = *ycb_object("ycb_mustard_bottle");
  return o;
}

HumanClosing human_mustard_closing() {
  const std::vector<GraspHypothesis> hyps = box_hypotheses(mustard());
  for (std::size_t i = 0; i < hyps.size(); ++i)
    if (demonstrate(mustard(), hyps[i], static_cast<int>(i)).stable())
      if (auto closed = close_human_grasp(mustard(), hyps[i])) return std::move(*closed);
  std::fprintf(stderr, "bench_physics: no stable demonstration of the mustard bottle\n");
  std::exit(1);
}

HandScene<models::human_hand> human_mustard() { return human_mustard_closing().scene; }

template <class Scene>
void run_topograsp(benchmark::State& state, const Scene& start) {
  Scene scene = start;
  for (auto _ : state) {
    scene = start;  // same capacity: no allocation
    for (int i = 0; i < batch; ++i) benchmark::DoNotOptimize(scene.step());
  }
  state.counters["steps/s"] = benchmark::Counter(static_cast<double>(state.iterations() * batch),
                                                 benchmark::Counter::kIsRate);
  state.counters["contacts"] = scene.hand_contacts();
  state.counters["held"] =
      (scene.object_in_hand().translation() - start.object_in_hand().translation()).norm() < 0.02;
}

void BM_topograsp_sdh_bottle(benchmark::State& state) {
  static const auto scene = sdh_bottle();
  run_topograsp(state, scene);
}
BENCHMARK(BM_topograsp_sdh_bottle)->Unit(benchmark::kMicrosecond);

void BM_topograsp_human_hammer(benchmark::State& state) {
  static const auto scene = human_hammer();
  run_topograsp(state, scene);
}
BENCHMARK(BM_topograsp_human_hammer)->Unit(benchmark::kMicrosecond);

void BM_topograsp_human_mustard(benchmark::State& state) {
  static const auto scene = human_mustard();
  run_topograsp(state, scene);
}
BENCHMARK(BM_topograsp_human_mustard)->Unit(benchmark::kMicrosecond);

// Making the mesh object: reading the 1500-triangle file, its checks, mass properties and BADGr.
void BM_ycb_object_mustard(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(ycb_object("ycb_mustard_bottle"));
}
BENCHMARK(BM_ycb_object_mustard)->Unit(benchmark::kMillisecond);

// The planner's query (approach_until_contact, placement): the distance between the human hand's
// shapes at a grasp and the object's pieces, on the mesh object's boxes and on the built-in
// bottle's cylinders.
void run_distance(benchmark::State& state, const GraspObject& object, const Vec<26>& q) {
  const Composite shape = object.composite();
  KinematicsData<models::human_hand_free> d;
  forward_kinematics(d, q);
  for (auto _ : state) benchmark::DoNotOptimize(hand_object_distance(d, shape));
  state.counters["pieces"] = static_cast<double>(shape.parts().size());
}

void BM_hand_distance_mustard(benchmark::State& state) {
  static const Vec<26> q = human_mustard_closing().touched;
  run_distance(state, mustard(), q);
}
BENCHMARK(BM_hand_distance_mustard)->Unit(benchmark::kNanosecond);

void BM_hand_distance_bottle(benchmark::State& state) {
  static const GraspObject bottle = objects::bottle();
  static const Vec<26> q = [] {
    for (const GraspHypothesis& h : box_hypotheses(bottle))
      if (auto closed = close_human_grasp(bottle, h)) return closed->touched;
    return Vec<26>(Vec<26>::Zero());
  }();
  run_distance(state, bottle, q);
}
BENCHMARK(BM_hand_distance_bottle)->Unit(benchmark::kNanosecond);

template <class Scene>
void run_suite(benchmark::State& state, const Scene& closed) {
  StabilityResult r;
  StabilityOptions every;
  every.every_test = true;  // the full suite, whatever the verdict
  for (auto _ : state) {
    r = stability_suite(closed, every);
    benchmark::DoNotOptimize(r);
  }
  int steps = 0;
  for (const StabilityRecord& t : r.tests) steps += t.steps;
  state.counters["stable"] = r.stable;
  state.counters["steps"] = steps;
}

void BM_stability_suite_sdh_bottle(benchmark::State& state) {
  static const auto scene = sdh_bottle();
  run_suite(state, scene);
}
BENCHMARK(BM_stability_suite_sdh_bottle)->Unit(benchmark::kMillisecond);

void BM_stability_suite_human_hammer(benchmark::State& state) {
  static const auto scene = human_hammer();
  run_suite(state, scene);
}
BENCHMARK(BM_stability_suite_human_hammer)->Unit(benchmark::kMillisecond);

#ifdef TOPOGRASP_HAVE_MUJOCO
// The motors of the MuJoCo scenes: the model's effort limits, or 1 N m per joint where the model
// gives none (printed at the end, so a number measured that way says so).
bool assumed_efforts = false;

template <const auto& M>
MjcfOptions mujoco_options(double max_time_step, bool noslip) {
  MjcfOptions o;
  o.max_time_step = max_time_step;
  if (!noslip) o.noslip_iterations = 0;
  // A contact and a weld MuJoCo resolves at this step: at least two steps long (MjcfOptions).
  o.contact_timeconst = std::max(o.contact_timeconst, 2.0 * max_time_step);
  o.hand_timeconst = std::max(o.hand_timeconst, 2.0 * max_time_step);
  for (int i = 0; i < M.nq; ++i)
    if (!(M.joint_spec(i).effort > 0.0)) {
      o.effort.assign(static_cast<std::size_t>(M.nq), 1.0);
      assumed_efforts = true;
      break;
    }
  return o;
}

// The same grasp as the built-in benchmark, articulated (joints, torque-limited position
// servos, couplings) in MuJoCo through MujocoScene: one step() is one scene step of 1/60 s, in
// MuJoCo steps of at most max_time_step; noslip false: without MuJoCo's noslip solver (its own
// default, soft friction), which the judge runs (MjcfOptions::noslip_iterations).
template <const auto& M>
void run_mujoco(benchmark::State& state, const HandScene<M>& built_in, double max_time_step,
                bool noslip = true) {
  std::optional<MujocoScene> start;
  try {
    start.emplace(built_in, mujoco_options<M>(max_time_step, noslip));
  } catch (const invalid_argument& e) {
    state.SkipWithError(e.what());
    return;
  }
  MujocoScene scene = *start;
  for (auto _ : state) {
    scene = *start;  // mj_copyData into the same mjData: no allocation
    for (int i = 0; i < batch; ++i) benchmark::DoNotOptimize(scene.step());
  }
  state.counters["steps/s"] = benchmark::Counter(static_cast<double>(state.iterations() * batch),
                                                 benchmark::Counter::kIsRate);
  state.counters["substeps"] = scene.substeps();
  state.counters["contacts"] = scene.hand_contacts();
  state.counters["held"] =
      (scene.object_in_hand().translation() - start->object_in_hand().translation()).norm() < 0.02;
}

// At 2 ms (what the judge runs: 9 MuJoCo steps per 1/60 s) and at 1/60 s (one MuJoCo step per
// scene step, the built-in's own time step; too long for MuJoCo to hold a grasp).
void BM_mujoco_sdh_bottle(benchmark::State& state) {
  static const auto scene = sdh_bottle();
  run_mujoco(state, scene, 0.002);
}
BENCHMARK(BM_mujoco_sdh_bottle)->Unit(benchmark::kMicrosecond);

void BM_mujoco_human_hammer(benchmark::State& state) {
  static const auto scene = human_hammer();
  run_mujoco(state, scene, 0.002);
}
BENCHMARK(BM_mujoco_human_hammer)->Unit(benchmark::kMicrosecond);

void BM_mujoco_soft_friction_sdh_bottle(benchmark::State& state) {
  static const auto scene = sdh_bottle();
  run_mujoco(state, scene, 0.002, false);
}
BENCHMARK(BM_mujoco_soft_friction_sdh_bottle)->Unit(benchmark::kMicrosecond);

void BM_mujoco_soft_friction_human_hammer(benchmark::State& state) {
  static const auto scene = human_hammer();
  run_mujoco(state, scene, 0.002, false);
}
BENCHMARK(BM_mujoco_soft_friction_human_hammer)->Unit(benchmark::kMicrosecond);

void BM_mujoco_60hz_sdh_bottle(benchmark::State& state) {
  static const auto scene = sdh_bottle();
  run_mujoco(state, scene, 1.0 / 60.0);
}
BENCHMARK(BM_mujoco_60hz_sdh_bottle)->Unit(benchmark::kMicrosecond);

void BM_mujoco_60hz_human_hammer(benchmark::State& state) {
  static const auto scene = human_hammer();
  run_mujoco(state, scene, 1.0 / 60.0);
}
BENCHMARK(BM_mujoco_60hz_human_hammer)->Unit(benchmark::kMicrosecond);

void BM_mujoco_human_mustard(benchmark::State& state) {
  static const auto scene = human_mustard();
  run_mujoco(state, scene, 0.002);
}
BENCHMARK(BM_mujoco_human_mustard)->Unit(benchmark::kMicrosecond);
#endif

// Console output plus, at the end, MuJoCo's CPU time per step over topograsp's for each scene
// (CPU time: the 2-core CI machine is shared, so wall time is noisy).
class RatioReporter : public benchmark::ConsoleReporter {
 public:
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& r : runs)
      if (r.run_type == Run::RT_Iteration && r.iterations > 0)
        seconds_[r.benchmark_name()] = r.cpu_accumulated_time / static_cast<double>(r.iterations);
    ConsoleReporter::ReportRuns(runs);
  }
  void Finalize() override {
    ConsoleReporter::Finalize();
    for (const char* scene : {"sdh_bottle", "human_hammer", "human_mustard"}) {
      const auto t = seconds_.find(std::string("BM_topograsp_") + scene);
      const auto m = seconds_.find(std::string("BM_mujoco_") + scene);
      if (t == seconds_.end()) continue;
      std::printf("%-13s topograsp %8.0f steps/s", scene, batch / t->second);
      if (m != seconds_.end())
        std::printf("   MuJoCo (2 ms steps) %8.0f steps/s   ratio %.2fx", batch / m->second,
                    m->second / t->second);
      const auto soft = seconds_.find(std::string("BM_mujoco_soft_friction_") + scene);
      if (soft != seconds_.end())
        std::printf("   MuJoCo without noslip %8.0f steps/s   ratio %.2fx", batch / soft->second,
                    soft->second / t->second);
      const auto m60 = seconds_.find(std::string("BM_mujoco_60hz_") + scene);
      if (m60 != seconds_.end())
        std::printf("   MuJoCo (1/60 s steps) %8.0f steps/s   ratio %.2fx", batch / m60->second,
                    m60->second / t->second);
      std::printf("   (steps of the scene, 1/60 s each)\n");
    }
#ifdef TOPOGRASP_HAVE_MUJOCO
    if (assumed_efforts)
      std::printf("MuJoCo motors: 1 N m per joint where the model gives no effort limit\n");
#endif
  }

 private:
  std::map<std::string, double> seconds_;
};

}  // namespace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  RatioReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter);
  benchmark::Shutdown();
  return 0;
}
