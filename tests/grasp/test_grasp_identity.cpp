// SPDX-License-Identifier: BSD-3-Clause
#include <catch2/catch.hpp>

#include <topograsp/grasp/grasp_identity.hpp>
#include <topograsp/grasp/hypothesis.hpp>
#include <topograsp/grasp/object.hpp>

using namespace topograsp;

namespace {

// The rotation of `angle` about `axis`.
Mat3 turn(const Vec3& axis, double angle) { return Mat3(Eigen::AngleAxisd(angle, axis)); }

// True if some rotation of s is R (to 1e-9).
bool has_rotation(const ObjectSymmetry& s, const Mat3& R) {
  return std::any_of(s.rotations.begin(), s.rotations.end(),
                     [&](const Mat3& S) { return (S - R).cwiseAbs().maxCoeff() < 1e-9; });
}

// The pose T turned by R about c.
Eigen::Isometry3d turned(const Eigen::Isometry3d& T, const Mat3& R, const Vec3& c) {
  Eigen::Isometry3d out = T;
  out.linear() = R * T.linear();
  out.translation() = c + R * (T.translation() - c);
  return out;
}

}  // namespace

TEST_CASE("object_symmetry finds the shapes' rotations and nothing else", "[grasp][identity]") {
  const ObjectSymmetry hammer = object_symmetry(objects::hammer());
  // The head is centred on the handle's axis (x): a half turn about it, and no axis.
  CHECK(hammer.rotations.size() == 2);
  CHECK(has_rotation(hammer, turn(Vec3::UnitX(), pi)));
  CHECK_FALSE(hammer.axis);
  const ObjectSymmetry bottle = object_symmetry(objects::bottle());
  // Round about z, but the neck is on top: no half turn that flips it.
  REQUIRE(bottle.axis);
  CHECK(std::abs(bottle.axis->z()) == Approx(1.0));
  CHECK(bottle.rotations.size() == 1);
  CHECK_FALSE(bottle.isotropic);
  const ObjectSymmetry can = object_symmetry(objects::can());
  REQUIRE(can.axis);
  CHECK(has_rotation(can, turn(Vec3::UnitX(), pi)));             // a can flips end over end
  CHECK(object_symmetry(objects::mug()).rotations.size() == 1);  // the handle breaks them all
  CHECK(object_symmetry(objects::box()).rotations.size() == 4);  // three half turns
  CHECK(object_symmetry(objects::ball()).isotropic);
}

TEST_CASE("same_grasp: equal up to a symmetry and the tolerances", "[grasp][identity]") {
  const GraspObject bottle = objects::bottle();
  const ObjectSymmetry s = object_symmetry(bottle);
  Eigen::Isometry3d a = Eigen::Isometry3d::Identity();
  a.linear() = turn(Vec3(1, 2, 3).normalized(), 0.8);
  a.translation() = Vec3(0.06, 0.01, 0.08);
  const Vec<20> q = Vec<20>::Constant(0.3);
  // Anywhere around the bottle's axis it is the same grasp.
  for (const double angle : {0.4, 2.0, -2.9})
    CHECK(same_grasp(a, q, turned(a, turn(*s.axis, angle), s.centre), q, s));
  // Moved 2 cm up the bottle, turned 20 degrees about the approach, or one joint 0.2 rad: not.
  Eigen::Isometry3d up = a;
  up.translation().z() += 0.02;
  CHECK_FALSE(same_grasp(a, q, up, q, s));
  Eigen::Isometry3d rolled = a;
  rolled.linear() = a.linear() * turn(Vec3::UnitX(), deg(20.0));
  CHECK_FALSE(same_grasp(a, q, rolled, q, s));
  Vec<20> bent = q;
  bent[5] += 0.2;
  CHECK_FALSE(same_grasp(a, q, a, bent, s));
  // Within the tolerances: 5 mm, 10 degrees, 0.1 rad.
  Eigen::Isometry3d near = a;
  near.translation().z() += 0.005;
  near.linear() = a.linear() * turn(Vec3::UnitY(), deg(10.0));
  Vec<20> q2 = q;
  q2[3] += 0.1;
  CHECK(same_grasp(a, q, near, q2, s));
  // The hammer: only its half turn about the handle.
  const ObjectSymmetry h = object_symmetry(objects::hammer());
  CHECK(same_grasp(a, q, turned(a, turn(Vec3::UnitX(), pi), h.centre), q, h));
  CHECK_FALSE(same_grasp(a, q, turned(a, turn(Vec3::UnitX(), 0.5 * pi), h.centre), q, h));
  // A sphere: any rotation about its centre.
  const ObjectSymmetry ball = object_symmetry(objects::ball());
  CHECK(same_grasp(a, q, turned(a, turn(Vec3(3, -1, 2).normalized(), 1.3), ball.centre), q, ball));
}

TEST_CASE("grasp_clusters joins chains of the same grasp and names the first",
          "[grasp][identity]") {
  const ObjectSymmetry s = object_symmetry(objects::hammer());
  std::vector<Eigen::Isometry3d> poses(4, Eigen::Isometry3d::Identity());
  poses[1].translation().x() = 0.008;  // 8 mm from 0
  poses[2].translation().x() = 0.05;   // far from both
  poses[3].translation().x() = 0.016;  // 8 mm from 1, 16 from 0: joined through 1
  const std::vector<Vec<20>> q(4, Vec<20>::Zero());
  CHECK(grasp_clusters<Vec<20>>(poses, q, s) == std::vector<int>{0, 0, 2, 0});
  const std::vector<Vec<20>> three(3, Vec<20>::Zero());
  CHECK_THROWS_WITH(grasp_clusters<Vec<20>>(poses, three, s), Catch::StartsWith("joints"));
  CHECK_THROWS_WITH(object_symmetry(objects::hammer(), 0.0), Catch::StartsWith("tolerance"));
}

TEST_CASE("demonstrator_hypotheses: 8 rolls per face, each jittered once within bounds",
          "[grasp][hypotheses]") {
  const GraspObject hammer = objects::hammer();
  const std::vector<GraspHypothesis> box = box_hypotheses(hammer);
  const std::vector<GraspHypothesis> h = demonstrator_hypotheses(hammer, 1);
  REQUIRE(h.size() == box.size() / 4 * 8 * 2);
  for (std::size_t i = 0; i < h.size(); ++i) {
    const GraspHypothesis& x = h[i];
    const GraspHypothesis& face = box[i / 16 * 4];  // the face's turn-0 hypothesis
    CHECK(x.box == face.box);
    CHECK(x.face == face.face);
    CHECK(x.roll == static_cast<int>(i / 2 % 8));
    CHECK(x.approach.norm() == Approx(1.0));
    CHECK(x.up.norm() == Approx(1.0));
    CHECK(std::abs(x.up.dot(x.approach)) < 1e-12);
    if (i % 2 == 0) {  // the nominal one: on the face, along its normal
      CHECK(x.jitter_seed == 0);
      CHECK((x.centre - face.centre).norm() < 1e-12);
      CHECK((x.approach - face.approach).norm() < 1e-12);
    } else {  // within 1.5 cm along each face axis and 10 degrees of tilt, on the face's plane
      CHECK(x.jitter_seed != 0);
      const Vec3 d = x.centre - face.centre;
      CHECK(std::abs(d.dot(face.approach)) < 1e-12);
      CHECK(d.cwiseAbs().maxCoeff() <= 0.015 * std::sqrt(2.0) + 1e-12);
      CHECK(std::acos(std::min(1.0, x.approach.dot(face.approach))) <= deg(10.0) + 1e-9);
    }
  }
  // The first roll of the nominal ones is box_hypotheses' turn 0.
  CHECK((h[0].up - box[0].up).norm() < 1e-12);
  // Deterministic; the seed moves only the jittered ones.
  const std::vector<GraspHypothesis> again = demonstrator_hypotheses(hammer, 1);
  const std::vector<GraspHypothesis> other = demonstrator_hypotheses(hammer, 2);
  CHECK((again[1].centre - h[1].centre).norm() == 0.0);
  CHECK((other[0].centre - h[0].centre).norm() == 0.0);
  CHECK((other[1].centre - h[1].centre).norm() > 0.0);
  DemonstratorVariation v;
  v.rolls = 0;
  CHECK_THROWS_WITH(demonstrator_hypotheses(hammer, 1, v), Catch::StartsWith("variation.rolls"));
  v = {};
  v.max_tilt = -0.1;
  CHECK_THROWS_WITH(demonstrator_hypotheses(hammer, 1, v), Catch::StartsWith("variation.max_tilt"));
}

TEST_CASE("palm_angle: where an axis lies in the palm, either end, NaN end on",
          "[grasp][hypotheses]") {
  const Vec3 approach = Vec3::UnitX(), up = Vec3::UnitZ();
  const Vec3 thumb = up.cross(approach);  // +y
  CHECK(palm_angle(thumb, approach, up) == Approx(0.0).margin(1e-12));
  CHECK(palm_angle(-thumb, approach, up) == Approx(0.0).margin(1e-12));
  CHECK(palm_angle(up, approach, up) == Approx(0.5 * pi));
  CHECK(palm_angle(-up, approach, up) == Approx(0.5 * pi));
  CHECK(palm_angle((thumb + up).normalized(), approach, up) == Approx(deg(45.0)));
  CHECK(palm_angle(-(thumb + up).normalized(), approach, up) == Approx(deg(45.0)));
  CHECK(palm_angle((thumb - up).normalized(), approach, up) == Approx(deg(-45.0)));
  CHECK(std::isnan(palm_angle(approach, approach, up)));
  CHECK(std::isnan(palm_angle((approach + 0.2 * thumb).normalized(), approach, up)));
}

TEST_CASE("power_grip_hypotheses: the long axis in the palm's band, near the centre of mass",
          "[grasp][hypotheses]") {
  for (const GraspObject& object : {objects::hammer(), objects::bottle()}) {
    CAPTURE(object.name);
    const PowerGrip rule;
    const std::vector<GraspHypothesis> h = power_grip_hypotheses(object, 1);
    const Vec3 com = object.centre_of_mass();
    const int per_face = 2 * rule.variation.rolls * (rule.variation.jittered + 1);
    REQUIRE(!h.empty());
    REQUIRE(h.size() % static_cast<std::size_t>(per_face) == 0);
    int without_axis = 0;
    for (std::size_t i = 0; i < h.size(); ++i) {
      const GraspHypothesis& x = h[i];
      const GraspHypothesis& first = h[i / static_cast<std::size_t>(per_face) * per_face];
      CHECK(x.box == first.box);
      CHECK(x.face == first.face);
      const int roll = static_cast<int>(i) % per_face / (rule.variation.jittered + 1);
      const int copy = static_cast<int>(i) % (rule.variation.jittered + 1);
      CHECK(x.roll == roll);
      CHECK(x.approach.norm() == Approx(1.0));
      CHECK(std::abs(x.up.dot(x.approach)) < 1e-12);
      CHECK((x.jitter_seed == 0) == (copy == 0));
      if (copy != 0) continue;
      // The nominal one: the face's centre, along its normal, the centre of mass near the line.
      const GraspBox& box = object.boxes[static_cast<std::size_t>(x.box)];
      const Vec3 off = com - x.centre;
      CHECK((off - off.dot(x.approach) * x.approach).norm() <= rule.max_offset + 1e-12);
      // The long axis: the box's longest side where it is 1.1 times the next, else the
      // object's (the bottle's neck and shoulder: its axis, z).
      std::array<double, 3> half = box.half;
      std::sort(half.begin(), half.end());
      const auto longest =
          static_cast<int>(std::max_element(box.half.begin(), box.half.end()) - box.half.begin());
      const bool own = half[2] >= rule.long_ratio * half[1];
      if (!own) ++without_axis;
      const Vec3 L = own ? Vec3(box.pose.rotation().col(longest)) : Vec3::UnitZ();
      CHECK((own || object.name == "bottle"));
      CHECK(std::abs(L.dot(x.approach)) < 1e-9);  // never the palm on an end
      const int k = roll % rule.variation.rolls;
      const double expected =
          rule.band_low + (rule.band_high - rule.band_low) * k / (rule.variation.rolls - 1);
      CHECK(palm_angle(L, x.approach, x.up) == Approx(expected).margin(1e-9));
      // The end toward the thumb: the positive one for the first rolls.
      const double toward = L.dot(x.up.cross(x.approach));
      CHECK((roll < rule.variation.rolls ? toward > -1e-9 : toward < 1e-9));
    }
    if (object.name == "hammer") CHECK(without_axis == 0);
    // Fewer faces than box_hypotheses() reaches: the ends and the faces far from the centre of
    // mass are left out.
    CHECK(h.size() / static_cast<std::size_t>(per_face) < box_hypotheses(object).size() / 4);
  }
  // The hammer: the handle's far end (its centre 0.2 m from the centre of mass) is not gripped.
  const GraspObject hammer = objects::hammer();
  for (const GraspHypothesis& x : power_grip_hypotheses(hammer, 1))
    CHECK((x.centre - hammer.centre_of_mass()).norm() < 0.2);
  // The ball has no long axis: every reachable face, rolled evenly, the first as
  // box_hypotheses' turn 0.
  const GraspObject ball = objects::ball();
  const std::vector<GraspHypothesis> round = power_grip_hypotheses(ball, 1);
  const std::vector<GraspHypothesis> ball_faces = box_hypotheses(ball);
  REQUIRE(round.size() == ball_faces.size() / 4 * 40);
  for (std::size_t i = 0; i < round.size(); i += 4) {
    const GraspHypothesis& face = ball_faces[i / 40 * 4];
    const double angle = 2.0 * pi * round[i].roll / 10;
    const Mat3 R = ball.boxes[static_cast<std::size_t>(face.box)].pose.rotation();
    const int u = (face.face / 2 + 1) % 3, v = (face.face / 2 + 2) % 3;
    CHECK((round[i].up - (std::cos(angle) * R.col(u) + std::sin(angle) * R.col(v))).norm() < 1e-12);
  }
  // Deterministic; the seed moves only the jittered ones.
  const std::vector<GraspHypothesis> a = power_grip_hypotheses(hammer, 1),
                                     b = power_grip_hypotheses(hammer, 2);
  CHECK((a[0].centre - b[0].centre).norm() == 0.0);
  CHECK((a[1].centre - b[1].centre).norm() > 0.0);
  // The oblique crease only (docs/evaluation.md's example): one angle, either end, 8 per face.
  PowerGrip crease;
  crease.band_low = crease.band_high = deg(45.0);
  crease.variation.rolls = 1;
  const std::vector<GraspHypothesis> oblique = power_grip_hypotheses(hammer, 1, crease);
  CHECK(oblique.size() * 5 == a.size());
  for (std::size_t i = 0; i < oblique.size(); i += 4) {
    const GraspBox& box = hammer.boxes[static_cast<std::size_t>(oblique[i].box)];
    const auto longest = std::max_element(box.half.begin(), box.half.end()) - box.half.begin();
    CHECK(palm_angle(box.pose.rotation().col(longest), oblique[i].approach, oblique[i].up) ==
          Approx(deg(45.0)).margin(1e-9));
  }
  PowerGrip rule;
  rule.band_low = deg(50.0);
  rule.band_high = deg(40.0);
  CHECK_THROWS_WITH(power_grip_hypotheses(hammer, 1, rule), Catch::StartsWith("rule.band_low"));
  rule = {};
  rule.band_high = deg(100.0);
  CHECK_THROWS_WITH(power_grip_hypotheses(hammer, 1, rule), Catch::StartsWith("rule.band_low"));
  rule = {};
  rule.max_offset = -0.01;
  CHECK_THROWS_WITH(power_grip_hypotheses(hammer, 1, rule), Catch::StartsWith("rule.max_offset"));
  rule = {};
  rule.long_ratio = 0.5;
  CHECK_THROWS_WITH(power_grip_hypotheses(hammer, 1, rule), Catch::StartsWith("rule.long_ratio"));
  rule = {};
  rule.variation.jittered = -1;
  CHECK_THROWS_WITH(power_grip_hypotheses(hammer, 1, rule),
                    Catch::StartsWith("variation.jittered"));
  // Nothing within reach of the centre of mass: no hypothesis, no error.
  rule = {};
  rule.max_offset = 0.0;
  CHECK(power_grip_hypotheses(hammer, 1, rule).size() < power_grip_hypotheses(hammer, 1).size());
}
