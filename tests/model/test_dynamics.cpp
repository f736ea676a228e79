// SPDX-License-Identifier: BSD-3-Clause
// The hands carry their actuators and masses (docs/models.md, "Actuators and masses"): a test
// that fails if a value is dropped from a model.
#include <catch2/catch.hpp>

#include <string>

#include <topograsp/model/models.hpp>

using namespace topograsp;

namespace {

template <const auto& M>
void check_dynamics(double total_mass_min, double total_mass_max) {
  double total = 0.0;
  int actuated = 0;
  for (std::size_t l = 0; l < M.links.size(); ++l) {
    const Link& link = M.links[l];
    INFO(M.name.view() << " link " << link.spec.name.view());
    if (link.actuated) {
      ++actuated;
      CHECK(link.spec.effort > 0.0);
      CHECK(link.spec.velocity > 0.0);
      CHECK(link.spec.armature > 0.0);
    } else {
      // Mimic and fixed joints are driven through their source or not at all.
      CHECK(link.spec.effort == 0.0);
      CHECK(link.spec.velocity == 0.0);
      CHECK(link.spec.armature == 0.0);
    }
    bool has_shapes = false;
    for (const Shape& s : M.shapes) has_shapes = has_shapes || s.link == static_cast<int>(l);
    if (has_shapes) CHECK(link.spec.mass > 0.0);
    total += link.spec.mass;
  }
  CHECK(actuated == M.nq);
  CHECK(total > total_mass_min);
  CHECK(total < total_mass_max);
}

}  // namespace

TEST_CASE(
    "every actuated joint of the hands has a torque, speed and armature, every link with "
    "shapes a mass",
    "[model][dynamics]") {
  // Whole-hand masses: the SDH's URDF comment says 1.95 kg; the BarrettHand's links sum to
  // 1.10 kg; the human hand is 0.6 % of a 70 kg body (de Leva 1996).
  check_dynamics<models::schunk_sdh>(1.9, 2.0);
  check_dynamics<models::barrett_bh8>(1.0, 1.2);
  check_dynamics<models::human_hand>(0.40, 0.44);
}

TEST_CASE("the SDH's torques are the datasheet's: proximal 2.1 N m, distal 1.4 N m",
          "[model][dynamics]") {
  constexpr auto& m = models::schunk_sdh;
  const auto effort = [&](int link) { return m.links[static_cast<std::size_t>(link)].spec.effort; };
  CHECK(effort(m.link("finger_12")) == 2.1);
  CHECK(effort(m.link("finger_22")) == 2.1);
  CHECK(effort(m.link("thumb_2")) == 2.1);
  CHECK(effort(m.link("finger_13")) == 1.4);
  CHECK(effort(m.link("finger_23")) == 1.4);
  CHECK(effort(m.link("thumb_3")) == 1.4);
  // The mirrored knuckle has no motor of its own.
  CHECK(effort(m.link("knuckle_2")) == 0.0);
}

TEST_CASE("a human holding grasp: a few newtons at each fingertip, the thumb opposing them",
          "[model][dynamics]") {
  // The MCP torque over the finger's length is the fingertip force the torque holds (N).
  constexpr auto& m = models::human_hand;
  const auto tip_force = [&](int mcp, double length) {
    return m.links[static_cast<std::size_t>(mcp)].spec.effort / (models::human_hand_scale * length);
  };
  const double index = tip_force(m.link("index_mcp"), 0.0432 + 0.0296 + 0.0253);
  const double pinky = tip_force(m.link("pinky_mcp"), 0.0299 + 0.0211 + 0.0232);
  CHECK(index == Approx(8.0).epsilon(0.01));
  CHECK(pinky == Approx(4.0).epsilon(0.01));
  CHECK(index > pinky);
}
