// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <set>
#include <topograsp/grasp/hypothesis.hpp>

using namespace topograsp;

TEST_CASE("built-in objects are valid and of realistic size", "[grasp][objects]") {
  for (const std::string& name : objects::names()) {
    INFO(name);
    const auto o = objects::find(name);
    REQUIRE(o.has_value());
    CHECK(o->name == name);
    CHECK_NOTHROW(o->validate());
    CHECK(o->mass > 0.1);
    CHECK(o->mass < 1.0);
    CHECK(o->boxes.size() >= o->parts.size());  // long parts are split
  }
  CHECK_FALSE(objects::find("anvil").has_value());
  // The hammer's centre of mass lies between the handle's middle and its head.
  const Vec3 com = objects::hammer().centre_of_mass();
  CHECK(com.x() > 0.0);
  CHECK(com.x() < 0.153);
}

TEST_CASE("box hypotheses: four per reachable face, covered faces skipped", "[grasp][hypotheses]") {
  SECTION("a 0.27 m box splits into three boxes: 4 sides each plus top and bottom") {
    CHECK(objects::box().boxes.size() == 3);
    CHECK(box_hypotheses(objects::box()).size() == (3 * 4 + 2) * 4);
  }
  SECTION("a ball is one box with 6 faces, 24 hypotheses") {
    CHECK(box_hypotheses(objects::ball()).size() == 24);
  }
  SECTION("the bottle's body top and neck bottom are covered") {
    const GraspObject bottle = objects::bottle();
    const auto hyps = box_hypotheses(bottle);
    // body (0.17 m, two boxes): 8 sides and the bottom (its top is under the shoulder);
    // shoulder: 4 sides; neck: 4 sides and the top.
    CHECK(hyps.size() == (9 + 4 + 5) * 4);
    for (const GraspHypothesis& h : hyps) {
      CHECK(h.approach.norm() == Approx(1.0));
      CHECK(h.up.norm() == Approx(1.0));
      CHECK(std::abs(h.approach.dot(h.up)) < 1e-12);
    }
  }
  SECTION("the four turns of a face are distinct and orthogonal to its normal") {
    const auto hyps = box_hypotheses(objects::can());
    std::set<std::tuple<long, long, long>> ups;
    for (int k = 0; k < 4; ++k) {
      const Vec3 u = hyps[static_cast<std::size_t>(k)].up;
      ups.insert({std::lround(u.x()), std::lround(u.y()), std::lround(u.z())});
    }
    CHECK(ups.size() == 4);
  }
}

TEST_CASE("splitting a long box keeps its volume and extent", "[grasp][objects]") {
  const GraspBox b{at(0.1, 0.2, 0.3).rpy(0.3, 0.2, 0.1), {0.02, 0.13, 0.03}};
  std::vector<GraspBox> pieces;
  objects::detail::split_box(b, 0.12, pieces);
  REQUIRE(pieces.size() == 3);  // 0.26 m in pieces of at most 0.12 m
  double volume = 0.0;
  Vec3 centroid = Vec3::Zero();
  for (const GraspBox& p : pieces) {
    CHECK(p.half[1] == Approx(0.13 / 3));
    CHECK(p.half[0] == 0.02);
    volume += 8 * p.half[0] * p.half[1] * p.half[2];
    centroid += p.pose.translation() / 3.0;
  }
  CHECK(volume == Approx(8 * 0.02 * 0.13 * 0.03));
  CHECK((centroid - b.pose.translation()).norm() < 1e-12);
}

TEST_CASE("invalid objects are rejected with their name", "[grasp][bad-input]") {
  GraspObject o = objects::ball();
  o.mass = 0.0;
  CHECK_THROWS_WITH(o.validate(), Catch::Contains("ball.mass"));
  o = objects::ball();
  o.parts.clear();
  CHECK_THROWS_AS(o.validate(), topograsp::invalid_argument);
  o = objects::ball();
  o.parts[0].size[0] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(o.validate(), topograsp::invalid_argument);
}
