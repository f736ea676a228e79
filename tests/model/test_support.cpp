// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <topograsp/model/models.hpp>

using namespace topograsp;

namespace {

// The support of every link of M against a brute-force walk up the parent links: the same joints
// (fixed ones left out), in the same order (the link's own first), with the configuration entry,
// type, multiplier and offset of each read straight from the link. constexpr, so that it can be
// checked both at compile time and at run time.
template <const auto& M>
constexpr bool supports_match_parent_walk() {
  for (std::size_t l = 0; l < M.n_links; ++l) {
    const auto& s = M.support(static_cast<int>(l));
    if (s.size < 0 || s.size > static_cast<int>(M.n_links)) return false;
    int k = 0;
    for (int a = static_cast<int>(l); a >= 0; a = M.links[static_cast<std::size_t>(a)].parent) {
      const Link& link = M.links[static_cast<std::size_t>(a)];
      if (link.spec.type == JointType::fixed) continue;
      if (k >= s.size) return false;
      const SupportJoint& j = s.joints[static_cast<std::size_t>(k++)];
      if (j.link != a || j.q != link.q || j.type != link.spec.type) return false;
      if (j.multiplier != (link.actuated ? 1.0 : link.spec.multiplier)) return false;
      if (j.offset != (link.actuated ? 0.0 : link.spec.offset)) return false;
    }
    if (k != s.size) return false;
    // Unused entries stay default.
    for (std::size_t u = static_cast<std::size_t>(s.size); u < M.n_links; ++u)
      if (!(s.joints[u] == SupportJoint{})) return false;
  }
  return true;
}

}  // namespace

TEST_CASE("the support of every link is its parent walk without fixed joints", "[model][support]") {
  // STATIC_REQUIRE: the supports are computed by make_model at compile time, and checked there.
  STATIC_REQUIRE(supports_match_parent_walk<models::schunk_sdh>());
  STATIC_REQUIRE(supports_match_parent_walk<models::schunk_arm>());
  STATIC_REQUIRE(supports_match_parent_walk<models::schunk_arm_sdh>());
  STATIC_REQUIRE(supports_match_parent_walk<models::human_hand>());
  STATIC_REQUIRE(supports_match_parent_walk<models::barrett_bh8>());
  STATIC_REQUIRE(supports_match_parent_walk<models::schunk_sdh_free>());
  STATIC_REQUIRE(supports_match_parent_walk<models::human_hand_free>());
  STATIC_REQUIRE(supports_match_parent_walk<models::barrett_bh8_free>());
  // The same checks evaluated at run time, reading the model from memory.
  bool (*const at_run_time[])() = {
      supports_match_parent_walk<models::schunk_sdh>,
      supports_match_parent_walk<models::schunk_arm>,
      supports_match_parent_walk<models::schunk_arm_sdh>,
      supports_match_parent_walk<models::human_hand>,
      supports_match_parent_walk<models::barrett_bh8>,
      supports_match_parent_walk<models::schunk_sdh_free>,
      supports_match_parent_walk<models::human_hand_free>,
      supports_match_parent_walk<models::barrett_bh8_free>,
  };
  for (const auto check : at_run_time) CHECK(check());
}

TEST_CASE("the SDH supports list entries, mimic multipliers and types", "[model][support]") {
  constexpr auto& sdh = models::schunk_sdh;
  // The root and fixed links have no joints in their support.
  STATIC_REQUIRE(sdh.support(0).size == 0);
  // Finger 2's distal link: finger_23, finger_22, then the mimic knuckle_2 (entry 0, factor 1).
  constexpr auto& s = sdh.support(sdh.link("finger_23"));
  STATIC_REQUIRE(s.size == 3);
  STATIC_REQUIRE(s.joints[0].link == sdh.link("finger_23"));
  STATIC_REQUIRE(s.joints[0].q == sdh.joint("finger_23"));
  STATIC_REQUIRE(s.joints[1].q == sdh.joint("finger_22"));
  STATIC_REQUIRE(s.joints[2].link == sdh.link("knuckle_2"));
  STATIC_REQUIRE(s.joints[2].q == sdh.joint("knuckle"));
  STATIC_REQUIRE(s.joints[2].type == JointType::revolute);
  // The thumb does not move with the knuckle.
  constexpr auto& t = sdh.support(sdh.link("thumb_3"));
  STATIC_REQUIRE(t.size == 2);
  STATIC_REQUIRE(t.joints[1].q == sdh.joint("thumb_2"));
  // A range-for walks the used entries only.
  int n = 0;
  for (const SupportJoint& j : s) n += j.link >= 0 ? 1 : 0;
  CHECK(n == 3);
}

TEST_CASE("Barrett distal supports carry the mimic multiplier and offset", "[model][support]") {
  constexpr auto& bh = models::barrett_bh8;
  constexpr auto& s = bh.support(bh.link("finger_1_dist"));
  STATIC_REQUIRE(s.joints[0].link == bh.link("finger_1_dist"));
  STATIC_REQUIRE(s.joints[0].q == bh.joint("finger_1_med"));
  STATIC_REQUIRE(s.joints[0].multiplier == 0.3);
  STATIC_REQUIRE(s.joints[0].offset == 0.75);
  STATIC_REQUIRE(s.joints[1].multiplier == 1.0);
  STATIC_REQUIRE(s.joints[1].offset == 0.0);
}

TEST_CASE("a prismatic joint enters the support as prismatic", "[model][support]") {
  constexpr auto& f = models::schunk_sdh_free;
  // The free base: base_x, base_y, base_z slide, then three rotations; the palm sits on them.
  constexpr auto& s = f.support(f.link("palm"));
  STATIC_REQUIRE(s.size == 6);
  STATIC_REQUIRE(s.joints[5].q == f.joint("base_x"));
  STATIC_REQUIRE(s.joints[5].type == JointType::prismatic);
  STATIC_REQUIRE(s.joints[0].type == JointType::revolute);
}
