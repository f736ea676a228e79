// SPDX-License-Identifier: BSD-3-Clause
// grasp_transfer --hands: every hand's rates side by side from each hand's results.json
// (apps/grasp_transfer/hands_table.hpp).
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include <grasp_transfer/hands_table.hpp>

using namespace topograsp;

namespace {

// The parts of a results.json that the table reads: one hand, its model, two methods.
Json results(const std::string& model, int transplant_stable) {
  return Json::parse(R"({"config": {"hand": ")" + model + R"("}, "overall": {
    "demonstrations": {"stable": 33, "distinct": 13},
    "methods": {
      "topological": {"tested": 33, "stable": 28, "interval": [0.69, 0.93],
        "second_judge": {"engine": "mujoco", "stable_second": 19, "interval_second": [0.41, 0.73]},
        "paired": null, "paired_second": null,
        "distinct": {"tested": 13, "stable": 12, "interval": [0.67, 0.99]}, "paired_distinct": null},
      "transplant": {"tested": 33, "stable": )" +
                     std::to_string(transplant_stable) + R"(, "interval": [0.5, 0.8],
        "second_judge": {"engine": "mujoco", "stable_second": 25, "interval_second": [0.59, 0.87]},
        "paired": {"only_this": 1, "only_against": 0, "p_value": 1},
        "paired_second": {"only_this": 6, "only_against": 0, "p_value": 0.03125},
        "distinct": {"tested": 13, "stable": 12, "interval": [0.67, 0.99]},
        "paired_distinct": {"only_this": 0, "only_against": 0, "p_value": 1}}}}})");
}

}  // namespace

TEST_CASE("hands_summary gathers every hand's rates; hands_markdown tables them", "[apps]") {
  const Json summary =
      hands_summary({{"barrett", "barrett/results.json", results("barrett_bh8", 29)},
                     {"leap", "leap/results.json", results("leap_hand", 33)}});
  CHECK(summary.at("generator").as_string() == "topograsp grasp_transfer --hands");
  const auto& hands = summary.at("hands").as_array();
  REQUIRE(hands.size() == 2);
  CHECK(hands[0].at("hand").as_string() == "barrett");
  CHECK(hands[1].at("model").as_string() == "leap_hand");
  CHECK(hands[1].at("results").as_string() == "leap/results.json");
  CHECK(hands[1].at("methods").at("transplant").at("stable").as_number() == 33);
  CHECK(hands[0].at("demonstrations").at("distinct").as_number() == 13);
  const std::string md = hands_markdown(summary);
  CHECK_THAT(md, Catch::Contains("| hand | demonstrations | topological | transplant |"));
  CHECK_THAT(md, Catch::Contains("| barrett (barrett_bh8) | 33 | 28/33 = 85 % [69, 93]<br>mujoco: "
                                 "19/33 = 58 % [41, 73] | 29/33 = 88 % [50, 80]; 1 : 0, p = "
                                 "1<br>mujoco: 25/33 = 76 % [59, 87]; 6 : 0, p = 0.031 |"));
  // The distinct table: one demonstration per distinct grasp.
  CHECK_THAT(md, Catch::Contains("| leap (leap_hand) | 13 | 12/13 = 92 % [67, 99] | 12/13 = 92 % "
                                 "[67, 99]; 0 : 0, p = 1 |"));
}

TEST_CASE("hands_summary refuses a document that is not a results.json, naming it", "[apps]") {
  CHECK_THROWS_WITH(hands_summary({{"allegro", "allegro/results.json", Json::parse("{}")}}),
                    "--hands: allegro: allegro/results.json: overall: missing (not a results.json "
                    "of grasp_transfer)");
  CHECK_THROWS_WITH(
      hands_summary({{"allegro", "a.json", Json::parse(R"({"overall": {"methods": {}}})")}}),
      "--hands: allegro: a.json: config: missing (not a results.json of grasp_transfer)");
  CHECK_THROWS_WITH(hands_summary({{"allegro", "a.json",
                                    Json::parse(R"({"config": {"hand": "a"}, "overall": {}})")}}),
                    "--hands: allegro: a.json: overall.demonstrations: missing (not a "
                    "results.json of grasp_transfer)");
}
