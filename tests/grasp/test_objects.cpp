// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <set>
#include <topograsp/grasp/human_grasps.hpp>
#include <topograsp/grasp/hypothesis.hpp>
#include "support/throws.hpp"

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
  o = objects::hammer();
  o.densities.pop_back();
  test::check_throws_naming([&] { o.validate(); }, "hammer.materials");
  o = objects::hammer();
  o.densities[1] = -1.0;
  test::check_throws_naming([&] { o.validate(); }, "hammer.densities[1]");
}

TEST_CASE("objects have the masses of the real ones, from their materials", "[grasp][objects]") {
  CHECK(objects::hammer().mass == Approx(0.592).epsilon(0.01));
  CHECK(objects::bottle().mass == Approx(0.520).epsilon(0.01));
  CHECK(objects::mug().mass == Approx(0.35).epsilon(0.03));
  CHECK(objects::box().mass == Approx(0.45).epsilon(1e-9));
  CHECK(objects::ball().mass == Approx(0.2).epsilon(1e-9));
  CHECK(objects::can().mass == Approx(0.356).epsilon(0.01));
  for (const std::string& name : objects::names()) {
    const GraspObject o = *objects::find(name);
    INFO(name);
    REQUIRE(o.materials.size() == o.parts.size());
    REQUIRE(o.densities.size() == o.parts.size());
    // The mass is the parts' density times volume.
    CHECK(body_mass_properties<double>(o.parts, 0.0, 0.0, o.densities).mass ==
          Approx(o.mass).epsilon(1e-12));
  }
  CHECK(objects::hammer().materials[1].name == "steel");
  CHECK(objects::hammer().materials[0].surface == Surface::wood);
}

TEST_CASE("the hammer's steel head puts its centre of mass in the head half", "[grasp][objects]") {
  const GraspObject hammer = objects::hammer();
  // The hammer spans x in [-0.14, 0.169] (handle end to the head's face): its middle is 0.0145.
  // Head 0.454 kg at x = 0.153, handle 0.138 kg at 0: x = 0.454 * 0.153 / 0.592 = 0.117.
  const Vec3 com = hammer.centre_of_mass();
  CHECK(com.x() > 0.0145);
  CHECK(com.x() ==
        Approx(0.454 * 0.153 / (0.454 + 800.0 * pi * 0.014 * 0.014 * 0.28)).epsilon(1e-9));
  CHECK(std::abs(com.y()) < 1e-12);
  // A uniform density would put it 5 cm from the origin, in the handle.
  CHECK(hammer.composite().centroid().x() < 0.06);
}

TEST_CASE("friction comes from the table of materials per hand surface", "[grasp][objects]") {
  for (const HandSurface h : {HandSurface::human_skin, HandSurface::sdh_pad, HandSurface::barrett})
    for (int k = 0; k <= static_cast<int>(Surface::rubber); ++k) {
      const double mu = friction_coefficient(h, static_cast<Surface>(k));
      CHECK(mu > 0.1);
      CHECK(mu < 2.0);
    }
  // Skin on rubber grips better than on aluminium (Seo and Armstrong 2009: 0.9 and 0.6), paper
  // worst (Buchholz et al. 1988).
  CHECK(friction_coefficient(HandSurface::human_skin, Surface::rubber) >
        friction_coefficient(HandSurface::human_skin, Surface::aluminium));
  CHECK(friction_coefficient(HandSurface::human_skin, Surface::cardboard) <
        friction_coefficient(HandSurface::human_skin, Surface::pet));
  CHECK(to_string(Surface::pet) == "pet");
  CHECK(to_string(HandSurface::sdh_pad) == "sdh_pad");
  CHECK(hand_surface<models::human_hand>() == HandSurface::human_skin);
  CHECK(hand_surface<models::schunk_sdh>() == HandSurface::sdh_pad);
  CHECK(hand_surface<models::barrett_bh8>() == HandSurface::barrett);
}

TEST_CASE("object_spec fills the part densities and friction; a coefficient overrides the table",
          "[grasp][objects]") {
  const GraspObject hammer = objects::hammer();
  const ObjectSpec s = object_spec(hammer, HandSurface::human_skin);
  CHECK(s.mass == hammer.mass);
  CHECK(s.part_density == hammer.densities);
  REQUIRE(s.part_friction.size() == 2);
  CHECK(s.part_friction[0] == friction_coefficient(HandSurface::human_skin, Surface::wood));
  CHECK(s.part_friction[1] == friction_coefficient(HandSurface::human_skin, Surface::steel));
  const ObjectSpec sdh = object_spec(hammer, HandSurface::sdh_pad);
  CHECK(sdh.part_friction[1] == friction_coefficient(HandSurface::sdh_pad, Surface::steel));
  const ObjectSpec over = object_spec(hammer, HandSurface::sdh_pad, 0.3);
  CHECK(over.part_friction == std::vector<double>{0.3, 0.3});
  CHECK(over.part_density == hammer.densities);
  test::check_throws_naming([&] { (void)object_spec(hammer, HandSurface::sdh_pad, -0.1); },
                            "friction");
  test::check_throws_naming(
      [&] {
        (void)object_spec(hammer, HandSurface::sdh_pad, std::numeric_limits<double>::quiet_NaN());
      },
      "friction");
  // An object without materials: uniform, the scene's friction (or the override).
  GraspObject plain = hammer;
  plain.materials.clear();
  plain.densities.clear();
  CHECK(object_spec(plain, HandSurface::human_skin).part_friction.empty());
  CHECK(object_spec(plain, HandSurface::human_skin).part_density.empty());
  CHECK(object_spec(plain, HandSurface::human_skin, 0.4).part_friction ==
        std::vector<double>{0.4, 0.4});
}
