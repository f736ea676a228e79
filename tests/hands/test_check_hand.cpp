// SPDX-License-Identifier: BSD-3-Clause
#include <string>

#include <catch2/catch.hpp>
#include <topograsp/grasp/check_hand.hpp>

#include "gripper_file.hpp"  // examples/import_hand: gripper.xml with gripper.json

using namespace topograsp;

namespace {

namespace tg = topograsp::test_hands::gripper;

// The example's gripper as a new user might get it wrong: the palm centre frame turned half a turn
// about its x axis (+z into the palm, +y from the fingers to the thumb), and the thumb's knuckle
// closing the wrong way.
constexpr auto wrong_links = [] {
  auto links = tg::links;
  for (LinkSpec& l : links)
    if (l.name.view() == "thumb_proximal") l.closing = -1.0;
  return links;
}();
constexpr auto wrong_gripper =
    make_model("wrong_gripper", wrong_links, tg::shapes,
               join(tg::frames, frames(frame("palm_turned", "palm", at(0, 0, 0.01).rpy(pi, 0, 0)))),
               hand("palm_turned",
                    finger("finger_1", {"finger_1_proximal", "finger_1_distal", "finger_1_tip"}),
                    finger("finger_2", {"finger_2_proximal", "finger_2_distal", "finger_2_tip"}),
                    thumb("thumb", {"thumb_proximal", "thumb_distal", "thumb_tip"})));

bool has(const HandCheck& c, const std::string& fragment) {
  for (const std::string& p : c.problems)
    if (p.find(fragment) != std::string::npos) return true;
  return false;
}

}  // namespace

TEST_CASE("hands: check_hand passes a hand described right and holds the trial objects",
          "[grasp][check_hand]") {
  const HandCheck c = check_hand<tg::model>();
  for (const std::string& p : c.problems) UNSCOPED_INFO(p);
  CHECK(c.problems.empty());
  REQUIRE(c.trials.size() == 2);
  CHECK(c.trials[0].object == "ball");
  CHECK(c.trials[1].object == "cylinder");
  for (const HandTrial& t : c.trials) {
    INFO(t.object << ": " << t.reason);
    CHECK(t.contacts > 0);
  }
  CHECK(c.ok());
}

TEST_CASE("hands: check_hand says what a new user's description got wrong",
          "[grasp][check_hand][bad-input]") {
  const HandCheck c = check_hand<wrong_gripper>();
  for (const std::string& p : c.problems) UNSCOPED_INFO(p);
  CHECK(c.problems.size() == 3);  // these, and no complaint about the joints described right
  CHECK_FALSE(c.ok());
  CHECK(has(c, "the palm centre frame's +y should point from the thumb tip toward the fingertips"));
  CHECK(has(c, "half closed, the fingertips lie behind the palm centre frame's +z"));
  CHECK(has(c,
            "closing the joint thumb_proximal (direction -1) moves the tip of thumb away from "
            "the palm's front"));
  // The trial objects sit behind the palm: the fingers close on air, and it says so.
  for (const HandTrial& t : c.trials) {
    INFO(t.object);
    CHECK_FALSE(t.stable);
    CHECK(t.contacts == 0);
    CHECK_THAT(t.reason, Catch::StartsWith("closing ended with no contact"));
  }
  CHECK_THROWS_WITH(check_hand<tg::model>(HandCheckOptions{.size_fraction = 0.0}),
                    Catch::Contains("options.size_fraction"));
  CHECK_THROWS_WITH(check_hand<tg::model>(HandCheckOptions{.mass = -1.0}),
                    Catch::Contains("options.mass"));
}
