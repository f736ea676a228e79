// SPDX-License-Identifier: BSD-3-Clause
// Two judges of one grasp (judge_grasp): the same tests that decide in both, whichever decides;
// the hard shake, a stress reported apart, in the deciding engine only.
#include <string>

#include <catch2/catch.hpp>

#include <topograsp/grasp/transfer.hpp>

using namespace topograsp;

namespace {

// A demonstration of the bottle judged a second time by the built-in stepper itself, standing in
// for MuJoCo (the same engine: the verdicts must agree test for test); \p hard_shakes counts the
// second judge's calls that asked for a hard shake.
HumanGrasp judged_twice(bool second_decides, int& hard_shakes, bool every_test = false) {
  const GraspObject bottle = objects::bottle();
  GraspSimOptions sim;
  sim.stability.every_test = every_test;
  sim.second_judge_name = "builtin_again";
  sim.second_judge_decides = second_decides;
  sim.second_judge_human = [&hard_shakes](const HandScene<models::human_hand>& scene,
                                          const StabilityOptions& o) {
    hard_shakes += o.hard_shake.steps > 0 ? 1 : 0;
    return stability_suite(scene, o);
  };
  return demonstrate(bottle, box_hypotheses(bottle)[0], 0, sim);
}

}  // namespace

TEST_CASE("the hard shake runs in the engine that decides, every other test in both",
          "[grasp][judge]") {
  for (const bool second_decides : {false, true}) {
    CAPTURE(second_decides);
    int hard_shakes = 0;
    const HumanGrasp g = judged_twice(second_decides, hard_shakes);
    REQUIRE(g.reached);
    REQUIRE(g.second);
    REQUIRE(g.stable());  // the bottle's first box hypothesis: a stable power grasp
    CHECK(hard_shakes == (second_decides ? 1 : 0));
    const StabilityResult& deciding = g.stability;
    const StabilityResult& other = *g.second;
    CHECK(deciding.stable == other.stable);
    for (std::size_t i = 0; i + 1 < k_stability_tests; ++i) {
      CAPTURE(deciding.tests[i].name);
      CHECK(deciding.tests[i].passed == other.tests[i].passed);
      CHECK(deciding.tests[i].steps == other.tests[i].steps);
      CHECK(deciding.tests[i].translation == other.tests[i].translation);
    }
    CHECK(deciding.hard_shake().steps > 0);
    CHECK(other.hard_shake().steps == 0);
    CHECK_FALSE(other.hard_shake().passed);
    CHECK(other.hard_shake().reason == k_hard_shake_deciding_only);
  }
}

TEST_CASE("every_test runs the hard shake in both judges", "[grasp][judge]") {
  int hard_shakes = 0;
  const HumanGrasp g = judged_twice(false, hard_shakes, true);
  REQUIRE(g.second);
  CHECK(hard_shakes == 1);
  CHECK(g.stability.hard_shake().steps > 0);
  CHECK(g.second->hard_shake().steps == g.stability.hard_shake().steps);
  CHECK(g.second->hard_shake().reason != k_hard_shake_deciding_only);
}

TEST_CASE("with the hard shake off, neither judge runs it and neither says another would",
          "[grasp][judge]") {
  const GraspObject bottle = objects::bottle();
  GraspSimOptions sim;
  sim.stability.hard_shake.steps = 0;
  sim.second_judge_human = [](const HandScene<models::human_hand>& scene,
                              const StabilityOptions& o) { return stability_suite(scene, o); };
  const HumanGrasp g = demonstrate(bottle, box_hypotheses(bottle)[0], 0, sim);
  REQUIRE(g.second);
  for (const StabilityResult* r : {&g.stability, &*g.second}) {
    CHECK(r->hard_shake().steps == 0);
    CHECK(r->hard_shake().reason == "not run (options.hard_shake.steps is 0)");
  }
}
