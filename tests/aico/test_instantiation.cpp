// SPDX-License-Identifier: BSD-3-Clause
// Every class template of the aico module instantiated explicitly, in both modes.
#include <catch2/catch.hpp>

#include <topograsp/aico.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/render/svg_plot.hpp>

#include "stacks.hpp"
#include "wrap_scene.hpp"

namespace topograsp {
using InstReach = test::ReachStack<models::schunk_arm, models::schunk_arm.frame("flange")>;
using InstTopo = TopologicalStack<test::WrapBase, WindingTask<test::wrap_robot, 2>>;
template class AicoProblem<models::schunk_arm, InstReach, AicoMode::dynamic>;
template class AicoProblem<models::schunk_arm, InstReach, AicoMode::kinematic>;
template struct AicoWorkspace<models::schunk_arm, InstReach, AicoMode::dynamic>;
template struct AicoWorkspace<models::schunk_arm, InstReach, AicoMode::kinematic>;
template struct AicoResult<7>;
template struct TopologicalResult<14, 2>;
template struct TopologicalStack<test::WrapBase, WindingTask<test::wrap_robot, 2>>;
template struct detail::Transition<7, AicoMode::dynamic>;
template struct detail::Transition<7, AicoMode::kinematic>;
}  // namespace topograsp

TEST_CASE("the aico stacks model TaskStack", "[aico][static]") {
  STATIC_REQUIRE(topograsp::TaskStack<topograsp::InstReach>);
  STATIC_REQUIRE(topograsp::TaskStack<topograsp::InstTopo>);
  STATIC_REQUIRE(topograsp::InstTopo::dim == topograsp::test::WrapBase::dim + 2);
  STATIC_REQUIRE(topograsp::InstTopo::task_dims.size() == 4);
}

TEST_CASE("the SVG plot writer draws axes, series and legend", "[aico][svg]") {
  topograsp::SvgLinePlot plot("Windings", "step t", "w");
  plot.add_series("a < b", {0.0, 1.0, 2.0}, {0.1, 0.5, 0.9});
  plot.add_reference("goal", 0.8);
  const std::string svg = plot.str();
  CHECK(svg.find("<svg") != std::string::npos);
  CHECK(svg.find("<polyline") != std::string::npos);
  CHECK(svg.find("a &lt; b") != std::string::npos);  // escaped legend label
  CHECK(svg.find(">0.8<") != std::string::npos);     // a nice tick on the y axis
  CHECK(svg.find("stroke-dasharray") != std::string::npos);
  CHECK_THROWS_AS(plot.add_series("bad", {0.0, 1.0}, {0.0}), topograsp::invalid_argument);
  CHECK_THROWS_AS(plot.add_series("nan", {0.0}, {std::nan("")}), topograsp::invalid_argument);
}

TEST_CASE("every aico enum has a name, and an unknown value is named so", "[aico][static]") {
  using namespace topograsp;
  STATIC_REQUIRE(to_string(AicoMode::dynamic) == "dynamic");
  STATIC_REQUIRE(to_string(AicoMode::kinematic) == "kinematic");
  STATIC_REQUIRE(to_string(SweepMode::symmetric) == "symmetric");
  STATIC_REQUIRE(to_string(SweepMode::local_gauss_newton) == "local_gauss_newton");
  STATIC_REQUIRE(to_string(TopologicalMode::direct) == "direct");
  STATIC_REQUIRE(to_string(TopologicalMode::coupled) == "coupled");
  STATIC_REQUIRE(to_string(AicoTermination::step_tolerance) == "step_tolerance");
  STATIC_REQUIRE(to_string(AicoTermination::cost_tolerance) == "cost_tolerance");
  STATIC_REQUIRE(to_string(AicoTermination::max_sweeps) == "max_sweeps");
  STATIC_REQUIRE(to_string(AicoTermination::max_rejections) == "max_rejections");
  STATIC_REQUIRE(to_string(AicoTermination::non_finite) == "non_finite");
  STATIC_REQUIRE(to_string(AicoTermination::factorisation) == "factorisation");
  STATIC_REQUIRE(to_string(static_cast<AicoTermination>(6)) == "unknown");
  STATIC_REQUIRE(to_string(static_cast<SweepMode>(-1)) == "unknown");
}
