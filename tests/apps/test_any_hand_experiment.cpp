// SPDX-License-Identifier: BSD-3-Clause
// The experiment with another hand than the SDH (grasp_transfer --hand): run_experiment<M> on the
// Barrett hand, its results.json against the shipped schema with the Barrett's joints by name, its
// scenes held in MuJoCo, and the options it refuses.
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <grasp_transfer/experiment.hpp>
#include <grasp_transfer/journal.hpp>
#include <grasp_transfer/results.hpp>
#include <topograsp/io/json_schema.hpp>
#include <topograsp/io/ycb_objects.hpp>
#include <topograsp/model/models/barrett_bh8.hpp>
#ifdef TOPOGRASP_HAVE_MUJOCO
#include <topograsp/mujoco/mujoco_scene.hpp>
#endif

using namespace topograsp;

namespace {

constexpr auto& barrett = models::barrett_bh8;

ExperimentOptions barrett_options() {
  ExperimentOptions c;
  c.objects = {objects::bottle()};
  c.methods = {TransferMethod::topological, TransferMethod::autoclose, TransferMethod::transplant};
  c.max_hypotheses = 2;  // the bottle's hypothesis 0 is a stable demonstration
  c.jobs = 2;
  return c;
}

}  // namespace

// Left out where no end-to-end test runs (the sanitizer build, tests/CMakeLists.txt).
#ifndef TOPOGRASP_TESTS_RUN_NO_END_TO_END
TEST_CASE("the experiment on the Barrett hand: records by its joint names, scenes, schema",
          "[grasp][experiment][end_to_end]") {
  ExperimentOptions c = barrett_options();
  SecondJudge<barrett> second;
#ifdef TOPOGRASP_HAVE_MUJOCO
  c.judge = Judge::both;
  c.transfer.sim.second_judge_human = [](const HandScene<models::human_hand>& s,
                                         const StabilityOptions& o) {
    return stability_suite(MujocoScene(s), o);
  };
  second = [](const HandScene<barrett>& s, const StabilityOptions& o) {
    return stability_suite(MujocoScene(s), o);
  };
#endif
  // The MJCF text of every planned transfer, by (demonstration id, method), as grasp_transfer
  // writes it.
  std::map<std::pair<int, TransferMethod>, std::string> scenes;
  const HypothesisDoneFnOf<barrett> on_done = [&](const GraspObject& object, const HumanGrasp& g,
                                                  const std::vector<HandTransfer<barrett>>& ts) {
    for (const HandTransfer<barrett>& t : ts)
      if (t.planned)
        scenes[{g.id, t.method}] = grasp_mjcf<barrett>(
            object, t.hand_pose, t.q_closed, t.object_pose, t.closing.hold_torque, c.transfer);
  };
  const std::vector<ObjectResultOf<barrett>> results =
      run_experiment<barrett>(c, {}, on_done, second);
  REQUIRE(results.size() == 1);
  REQUIRE(results[0].stable_human() >= 1);
  const Json doc = Json::parse(results_json(c, results).dump(2));
  const Json schema = Json::parse(
      detail::read_text_file(data_directory() + "/schemas/results.schema.json", "schema"));
  CHECK(validate_json(doc, schema).empty());
  CHECK(doc.at("config").at("hand").as_string() == "barrett_bh8");
  // Every placed transfer's configurations hold the Barrett's joints, by its names.
  std::vector<std::string> names;
  for (int i = 0; i < barrett.nq; ++i) names.emplace_back(barrett.joint_name(i));
  int placed = 0;
  for (const Json& g : doc.at("grasps").as_array()) {
    if (g.at("method").as_string() == "human" || g.at("configurations").is_null()) continue;
    ++placed;
    for (const char* which : {"grasp", "closed"}) {
      const Json& joints = g.at("configurations").at(which).at("joints");
      std::vector<std::string> keys;
      for (const std::string& name : names)
        if (joints.contains(name)) keys.push_back(name);
      CHECK(keys == names);
    }
    // The topological plan's joints: the free base's six coordinates, then the Barrett's (no arm).
    if (g.at("method").as_string() == "topological" && !g.at("motion").is_null()) {
      std::vector<std::string> planned;
      for (const Json& j : g.at("motion").at("joints").as_array()) planned.push_back(j.as_string());
      std::vector<std::string> expected{"base_x",  "base_y",  "base_z",
                                        "base_rz", "base_ry", "base_rx"};
      expected.insert(expected.end(), names.begin(), names.end());
      CHECK(planned == expected);
      for (const Json& step : g.at("motion").at("q").as_array())
        CHECK(step.as_array().size() == expected.size());
    }
  }
  CHECK(placed == static_cast<int>(scenes.size()));
  CHECK(placed >= 1);
#ifdef TOPOGRASP_HAVE_MUJOCO
  // A scene both engines hold opens in MuJoCo with the hand holding the object: left alone for a
  // second under gravity, the object stays within 5 mm.
  int held = 0;
  for (const auto& ts : results[0].transfers)
    for (std::size_t k = 0; k < ts.size(); ++k) {
      const HandTransfer<barrett>& t = ts[k];
      if (!(t.stable() && t.second && t.second->stable)) continue;
      MujocoScene scene(scenes.at({results[0].transferred_ids[k], t.method}));
      const Vec3 start = scene.object_pose().translation();
      const int steps = static_cast<int>(1.0 / scene.time_step());
      for (int i = 0; i < steps; ++i) (void)scene.step();
      INFO(to_string(t.method));
      CHECK((scene.object_pose().translation() - start).norm() < 0.005);
      ++held;
    }
  CHECK(held >= 1);
#endif
}
#endif

TEST_CASE("the experiment on another hand refuses what only the SDH on the arm runs",
          "[grasp][experiment][bad-input]") {
  ExperimentOptions c = barrett_options();
  CHECK_NOTHROW(validate_experiment_options<barrett>(c));
  c.methods = {TransferMethod::topological, TransferMethod::closed_windings};
  CHECK_THROWS_WITH(validate_experiment_options<barrett>(c),
                    "methods: \"closed_windings\" runs with the SDH on the arm only; the "
                    "barrett_bh8 is placed on a free base (docs/transfer.md, \"Any hand\")");
  c.methods = {TransferMethod::shuffled_windings};
  CHECK_THROWS_WITH(validate_experiment_options<barrett>(c),
                    Catch::StartsWith("methods: \"shuffled_windings\" runs with the SDH"));
  CHECK_NOTHROW(validate_experiment_options(c));  // the SDH runs it
  c = barrett_options();
  c.arm_setting = true;
  CHECK_THROWS_WITH(validate_experiment_options<barrett>(c),
                    "arm_setting: the arm carries the SDH only; the barrett_bh8 is placed on a "
                    "free base (--setting hand)");
  c = barrett_options();
  c.judge = Judge::both;
  c.transfer.sim.second_judge_human = [](const HandScene<models::human_hand>&,
                                         const StabilityOptions&) { return StabilityResult{}; };
  // The SDH's second judge is not the Barrett's.
  c.transfer.sim.second_judge_sdh = [](const HandScene<models::schunk_sdh>&,
                                       const StabilityOptions&) { return StabilityResult{}; };
  CHECK_THROWS_WITH(validate_experiment_options<barrett>(c),
                    "judge: --judge both needs a second judge (transfer.sim.second_judge_human "
                    "and the barrett_bh8's)");
  const SecondJudge<barrett> judge = [](const HandScene<barrett>&, const StabilityOptions&) {
    return StabilityResult{};
  };
  CHECK_NOTHROW(validate_experiment_options<barrett>(c, judge));
}
