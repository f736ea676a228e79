// SPDX-License-Identifier: BSD-3-Clause
// The baselines of the fair experiment: fingertip mapping with its targets on the object's
// surface, the virtual-finger mapping (pad or palm opposition) and the closing corrections of the
// topological method.
#include <cmath>

#include <catch2/catch.hpp>

#include <topograsp/grasp/transfer.hpp>

using namespace topograsp;

namespace {

const HumanGrasp& demonstration(const GraspObject& object, int id) {
  static std::vector<std::pair<std::string, HumanGrasp>> cache;
  const std::string key = object.name + "/" + std::to_string(id);
  for (const auto& [k, g] : cache)
    if (k == key) return g;
  cache.emplace_back(key,
                     demonstrate(object, box_hypotheses(object)[static_cast<std::size_t>(id)], id));
  return cache.back().second;
}

}  // namespace

TEST_CASE("the fingertip targets lie a phalanx radius and the contact gap off the surface",
          "[grasp][transfer][baselines]") {
  const TransferOptions options;
  const double off = models::sdh_dims::phalanx_radius + options.sim.contact_gap;
  for (const auto& [object, id] : {std::pair{objects::hammer(), 47}, {objects::bottle(), 0}}) {
    CAPTURE(object.name, id);
    const HumanGrasp& g = demonstration(object, id);
    REQUIRE(g.stable());
    const Composite shape = object.composite();
    // off from the part each was put on; nearer only where another part (the hammer's head) is.
    for (const Vec3& p : fingertip_targets(object, g, options)) {
      const double d = detail::nearest_surface(shape, p).distance;
      CHECK(d <= off + 1e-9);
      CHECK(d >= off - 1e-3);
    }
  }
}

TEST_CASE("the fingertip targets keep a scale far beyond any hand out of reach",
          "[grasp][transfer][baselines][bad-input]") {
  const GraspObject hammer = objects::hammer();
  TransferOptions options;
  options.fingertip_scale = 1e6;
  const std::array<Vec3, 3> far = fingertip_targets(hammer, demonstration(hammer, 47), options);
  for (const Vec3& p : far) CHECK(p.norm() > 100.0);  // not pulled onto the object
}

TEST_CASE("a hand that overlaps the object opens until it is clear, keeping its knuckle",
          "[grasp][transfer][baselines]") {
  const GraspObject hammer = objects::hammer();
  const auto root_of = [&](int id) {
    return detail::sdh_root_for_grasp_centre(detail::sdh_grasp_target(demonstration(hammer, id)));
  };
  const auto distance = [&](const Eigen::Isometry3d& root, const Vec<7>& q) {
    constexpr auto& f = models::schunk_sdh_free;
    KinematicsData<f> d;
    forward_kinematics(
        d, place_frame<f>(root * Eigen::Translation3d(0, 0, models::sdh_dims::base_height),
                          f.frame("palm_centre"), q));
    return hand_object_distance(d, hammer.composite());
  };
  TransferOptions options;
  options.transplant_opening = 0.0;  // straight fingers through the handle
  const Vec<7> straight = transplant_preshape(options);
  // The SDH at the human's grasp of the handle's end: straight fingers cut the handle.
  const Eigen::Isometry3d root = root_of(20);
  REQUIRE(distance(root, straight) < 0.0);
  const Vec<7> opened = open_until_clear(hammer, root, straight, options.sim);
  INFO("opened " << opened.transpose());
  CHECK(distance(root, opened) >= options.sim.contact_gap);
  CHECK(opened[0] == straight[0]);
  for (const int i : {1, 3, 5}) {
    CHECK(opened[i] < 0.0);  // proximal joints opened outward, distal ones inward
    CHECK(opened[i + 1] == Approx(-opened[i]));
  }
  // Opened no further than needed: one step less still overlaps.
  Vec<7> less = opened;
  for (const int i : {1, 3, 5}) {
    less[i] += 0.05;
    less[i + 1] -= 0.05;
  }
  CHECK(distance(root, less) < options.sim.contact_gap);
  // A clear hand is returned as it is.
  CHECK(open_until_clear(hammer, root, opened, options.sim) == opened);
  // Where the palm itself cuts the handle (grasp 47), opening cannot clear it: fully open.
  const Vec<7> full = open_until_clear(hammer, root_of(47), straight, options.sim);
  CHECK(distance(root_of(47), full) < 0.0);
  for (const int i : {1, 3, 5}) {
    CHECK(full[i] == lower_limits<models::schunk_sdh>()[i]);
    CHECK(full[i + 1] == upper_limits<models::schunk_sdh>()[i + 1]);
  }
}

TEST_CASE("the chord of an object along a line", "[grasp][transfer][baselines]") {
  const GraspObject ball = objects::ball();  // r 0.045 at (0, 0, 0.045)
  const Composite shape = ball.composite();
  const Vec3 centre(0, 0, 0.045);
  CHECK(detail::chord_length(shape, centre, Vec3::UnitX()) == Approx(0.09).margin(2e-3));
  // From a point outside, on the line: the interval nearest it.
  CHECK(detail::chord_length(shape, Vec3(0.1, 0, 0.045), Vec3::UnitX()) ==
        Approx(0.09).margin(2e-3));
  // Off centre: a shorter chord, 2 sqrt(r^2 - 0.03^2) = 0.067.
  CHECK(detail::chord_length(shape, Vec3(0, 0.03, 0.045), Vec3::UnitX()) ==
        Approx(0.067).margin(2e-3));
  CHECK(detail::chord_length(shape, Vec3(0, 0.1, 0.045), Vec3::UnitX()) == 0.0);  // a miss
}

TEST_CASE("the virtual-finger mapping finds the opposition of the human grasp",
          "[grasp][transfer][baselines]") {
  const TransferOptions options;
  // A power wrap of the hammer's handle: the palm touches it and opposes the fingers, and the SDH
  // is placed as the transplant with the handle's chord as its aperture.
  const GraspObject hammer = objects::hammer();
  const HumanGrasp& wrap = demonstration(hammer, 47);
  REQUIRE(wrap.stable());
  const SdhTransfer palm = transfer_virtual_finger(hammer, wrap, options);
  CHECK(palm.planned);
  CHECK(palm.method == TransferMethod::virtual_finger);
  CHECK(palm.reason == "palm opposition");
  CHECK_FALSE(palm.source_winding.has_value());  // a baseline aims at no winding
  const Eigen::Isometry3d target = detail::sdh_grasp_target(wrap);
  CHECK(palm.hand_pose.linear().col(2).dot(target.linear().col(2)) == Approx(1.0));
  constexpr auto& sdh = models::schunk_sdh;
  KinematicsData<sdh> sd;
  forward_kinematics(sd, palm.q_open);
  const auto [thumb, fingers] = detail::opposition<sdh>(sd);
  const double chord =
      detail::chord_length(hammer.composite(), target.translation(), target.linear().col(0));
  // At least the chord and the margin (opened further only to clear the object).
  CHECK((fingers - thumb).norm() >= chord + options.virtual_finger_margin - 0.01);
  // A grasp of the hammer's head whose palm stays 15 mm off it: the thumb opposes the fingers,
  // and the SDH's thumb-to-fingers axis is turned onto the human's.
  const HumanGrasp& tips = demonstration(hammer, 65);
  REQUIRE(tips.stable());
  const SdhTransfer pad = transfer_virtual_finger(hammer, tips, options);
  CHECK(pad.planned);
  CHECK(pad.reason == "pad opposition");
  constexpr auto& h = models::human_hand;
  KinematicsData<h> hd;
  forward_kinematics(hd, tips.q);
  const auto at = [&](int f) {
    return Vec3(tips.hand_pose * hd.frame_p[static_cast<std::size_t>(f)]);
  };
  const Vec3 human = 0.25 * (at(h.frame("index_tip")) + at(h.frame("middle_tip")) +
                             at(h.frame("ring_tip")) + at(h.frame("pinky_tip"))) -
                     at(h.frame("thumb_tip"));
  forward_kinematics(sd, pad.q_open);
  const auto [t2, f2] = detail::opposition<sdh>(sd);
  CHECK((pad.hand_pose.linear() * (f2 - t2)).normalized().dot(human.normalized()) ==
        Approx(1.0).margin(1e-9));
}

TEST_CASE("the virtual-finger mapping refuses a human grasp with NaN",
          "[grasp][transfer][baselines][bad-input]") {
  const GraspObject hammer = objects::hammer();
  HumanGrasp bad = demonstration(hammer, 47);
  bad.q[3] = std::nan("");
  const SdhTransfer r = transfer_virtual_finger(hammer, bad);
  CHECK_FALSE(r.planned);
  CHECK(r.reason == "the human configuration is not finite");
}

TEST_CASE("closing corrections keep the plan whose closed windings are nearest the human's",
          "[grasp][transfer][baselines]") {
  const GraspObject hammer = objects::hammer();
  const HumanGrasp& g = demonstration(hammer, 47);
  TransferOptions options;
  const SdhTransfer plain = transfer_topological(hammer, g, options);
  options.closing_corrections = 2;
  const SdhTransfer corrected = transfer_topological(hammer, g, options);
  REQUIRE(plain.planned);
  REQUIRE(corrected.planned);
  const Vec2 y = g.descriptor.values;
  CHECK((corrected.winding - y).norm() <= (plain.winding - y).norm() + 1e-12);
  // Both record the human's windings, not the corrected targets they planned toward.
  CHECK(plain.source_winding == y);
  CHECK(corrected.source_winding == y);
  // The variant is the topological method with two corrections.
  CHECK(transfer_method_options(TransferMethod::closed_windings, TransferOptions{})
            .closing_corrections == 2);
  CHECK(TransferOptions{}.closing_corrections == 0);
}
