// SPDX-License-Identifier: BSD-3-Clause
// Any hand to any hand (grasp/transfer/hand.hpp, and the SDH's Table I methods it matches): hand
// profiles, the frame two hands meet in, the winding targets of a hand with more or fewer curves
// than the source, the fingertip correspondence, transfer_hand (every method) on an imported hand
// from the human hand and from the SDH, transfer_hand_on_arm, a source as data (SourceGrasp), and
// what they do with bad input.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include <catch2/catch.hpp>

#include <topograsp/grasp/transfer.hpp>
#include <topograsp/model/models/allegro_hand.hpp>
#include <topograsp/model/models/shadow_hand.hpp>

using namespace topograsp;

namespace {

// The first stable human demonstration on the bottle (cached: the tests share it).
const HumanGrasp& bottle_demonstration() {
  static const HumanGrasp g = [] {
    const GraspObject bottle = objects::bottle();
    const auto hyps = box_hypotheses(bottle);
    for (std::size_t i = 0; i < hyps.size(); ++i) {
      HumanGrasp d = demonstrate(bottle, hyps[i], static_cast<int>(i));
      if (d.stable()) return d;
    }
    return HumanGrasp{};
  }();
  return g;
}

// A topological transfer r of the human grasp g to the Allegro: planned, its targets the human's
// three largest windings (as demonstrate() took them on the free base and as the transfer takes
// them from the palm pose: equal to rounding), the plan moving the windings toward them, judged
// (the suite weighed the object), its joints within their limits.
void check_topological_allegro(const HandTransfer<models::allegro_hand>& r, const HumanGrasp& g) {
  INFO(r.reason);
  REQUIRE(r.planned);
  REQUIRE(r.source_winding.has_value());
  Eigen::VectorXd human(4);
  human = g.windings;
  CHECK((*r.source_winding - winding_targets<3>(human)).norm() < 1e-9);
  REQUIRE(r.winding_plan.size() >= 2);
  const Vec3 y = *r.source_winding;
  CHECK((r.winding_plan.back() - y).norm() < (r.winding_plan.front() - y).norm());
  CHECK(r.sweeps > 0);
  CHECK(r.stability.weight > 0.0);
  CHECK((r.q_open.array() >= lower_limits<models::allegro_hand>().array()).all());
  CHECK((r.q_open.array() <= upper_limits<models::allegro_hand>().array()).all());
}

}  // namespace

TEST_CASE("winding targets: the k largest source windings, the smallest repeated beyond them",
          "[any_hand]") {
  Eigen::VectorXd w(4);
  w << 0.3, 1.2, 0.7, 0.9;
  CHECK(winding_targets<2>(w) == Vec2(1.2, 0.9));  // the paper's descriptor
  CHECK(winding_targets<4>(w) == Vec<4>(1.2, 0.9, 0.7, 0.3));
  Eigen::VectorXd two(2);
  two << 0.4, 0.8;
  CHECK(winding_targets<3>(two) == Vec3(0.8, 0.4, 0.4));
  CHECK_THROWS_WITH(winding_targets<2>(Eigen::VectorXd()), Catch::Contains("windings"));
  two[1] = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(winding_targets<2>(two), Catch::Contains("windings"));
}

TEST_CASE("hand profiles: the SDH keeps its pre-shape rule, other hands open against closing",
          "[any_hand]") {
  const auto sdh = hand_profile<models::schunk_sdh>();
  CHECK(sdh.frame == models::schunk_sdh.find_frame("grasp_centre"));
  CHECK(sdh.opening == (Vec<7>() << 0, -1, 1, -1, 1, -1, 1).finished());
  const auto allegro = hand_profile<models::allegro_hand>();
  CHECK(allegro.frame == models::allegro_hand.find_frame("palm_centre"));
  CHECK(allegro.opening == -closing_directions<models::allegro_hand>());
  // The transplant pre-shape: the SDH's as transplant_preshape always made it; any hand's within
  // its limits however far it is asked to open.
  TransferOptions options;
  CHECK(opened_preshape<models::schunk_sdh>(0.7, options.sdh_preshape) ==
        (Vec<7>() << 0, -0.7, 0.7, -0.7, 0.7, -0.7, 0.7).finished());
  const Vec<16> q = opened_preshape<models::allegro_hand>(5.0, Vec<16>::Zero());
  CHECK((q.array() >= lower_limits<models::allegro_hand>().array()).all());
  CHECK((q.array() <= upper_limits<models::allegro_hand>().array()).all());
}

TEST_CASE("the start pre-shape turns a thumb that opposes by a turn, and only that", "[any_hand]") {
  constexpr auto& s = models::shadow_hand;
  const TransferOptions options;
  const Vec<s.nq> zero = clamp_to_limits<s>(Vec<s.nq>::Zero());
  const Vec<s.nq> q = base_preshape<s>(options);
  // Only THJ5 and THJ3 (rh_thbase, rh_thhub: the thumb turns, no closing direction) move.
  for (int i = 0; i < s.nq; ++i) {
    CAPTURE(s.joint_name(i));
    const std::string_view n = s.joint_name(i);
    if (n != "rh_thbase" && n != "rh_thhub") CHECK(q[i] == zero[i]);
  }
  CHECK(q != zero);
  CHECK((q.array() >= lower_limits<s>().array()).all());
  CHECK((q.array() <= upper_limits<s>().array()).all());
  // Closed, its thumb tip comes nearer the other tips than with the thumb unturned.
  const auto gap = [](const Vec<s.nq>& x) {
    KinematicsData<s> d;
    forward_kinematics(d, closed_targets<s>(x));
    const auto tip = [&](std::size_t f) {
      return world_point(d, s.fingers[f].points[static_cast<std::size_t>(s.fingers[f].size - 1)]);
    };
    Vec3 c = Vec3::Zero();
    for (std::size_t f = 0; f < s.fingers.size(); ++f)
      if (static_cast<int>(f) != s.thumb) c += tip(f);
    return (tip(static_cast<std::size_t>(s.thumb)) - c / 4.0).norm();
  };
  CHECK(gap(q) < gap(zero));
  // Hands that oppose through their closing joints keep their zero.
  CHECK(base_preshape<models::allegro_hand>(options) ==
        clamp_to_limits<models::allegro_hand>(Vec<16>::Zero()));
  CHECK(base_preshape<models::schunk_sdh>(options) == options.sdh_preshape);
}

TEST_CASE("two hands meet in one frame: root_for_grasp_frame undoes grasp_frame", "[any_hand]") {
  Eigen::Isometry3d root = Eigen::Isometry3d::Identity();
  root.linear() = Eigen::AngleAxisd(0.7, Vec3(1, 2, 3).normalized()).toRotationMatrix();
  root.translation() = Vec3(0.1, -0.2, 0.05);
  const Vec<16> q = Vec<16>::Constant(0.3);
  const HandGrasp<models::allegro_hand> a{root, clamp_to_limits<models::allegro_hand>(q)};
  const Eigen::Isometry3d back = root_for_grasp_frame<models::allegro_hand>(grasp_frame(a), a.q);
  CHECK((back.matrix() - root.matrix()).norm() < 1e-12);
  // The meeting frame's z is the hand's approach: for the Allegro its palm centre's +z.
  KinematicsData<models::allegro_hand> d;
  forward_kinematics(d, a.q);
  const Vec3 palm_z =
      root.linear() * frame_pose(d, models::allegro_hand.frame("palm_centre")).linear().col(2);
  CHECK((grasp_frame(a).linear().col(2) - palm_z).norm() < 1e-12);
  // The human's: its palm normal (human_hand_axes.approach), from its grasp centre.
  const HumanGrasp& g = bottle_demonstration();
  REQUIRE(g.stable());
  KinematicsData<models::human_hand> h;
  forward_kinematics(h, g.q);
  const Eigen::Isometry3d gc =
      g.hand_pose * frame_pose(h, models::human_hand.frame("grasp_centre"));
  const Eigen::Isometry3d meet = grasp_frame(source_grasp(g));
  CHECK((meet.translation() - gc.translation()).norm() < 1e-12);
  CHECK((meet.linear().col(2) - gc.linear() * human_hand_axes.approach).norm() < 1e-12);
}

TEST_CASE("the paper's autoclose pairs the palms: palm_frame, root_for_palm_frame, autoclose_grasp",
          "[any_hand][transfer]") {
  // root_for_palm_frame undoes palm_frame, for the SDH whose palm centre is not its grasp frame.
  Eigen::Isometry3d root = Eigen::Isometry3d::Identity();
  root.linear() = Eigen::AngleAxisd(-1.1, Vec3(3, -1, 2).normalized()).toRotationMatrix();
  root.translation() = Vec3(-0.05, 0.2, 0.1);
  const HandGrasp<models::schunk_sdh> s{root, TransferOptions{}.sdh_preshape};
  const Eigen::Isometry3d back = root_for_palm_frame<models::schunk_sdh>(palm_frame(s), s.q);
  CHECK((back.matrix() - root.matrix()).norm() < 1e-12);
  // The palm frame is turned as the grasp frame is, 7.45 cm nearer the SDH's flange than the
  // grasp centre's 15 cm, along the approach.
  const Eigen::Isometry3d palm = palm_frame(s), meet = grasp_frame(s);
  CHECK((palm.linear() - meet.linear()).norm() < 1e-12);
  CHECK((meet.translation() - palm.translation() -
         (0.15 - models::sdh_dims::base_height) * meet.linear().col(2))
            .norm() < 1e-12);

  // Autoclose from the human grasp: the SDH at its usual pre-shape, its palm centre on the line
  // through the human's palm centre along the human's approach, at or behind it (backed off only
  // as far as needed to clear the object), its approach the human's; then closed and judged.
  const GraspObject bottle = objects::bottle();
  const HumanGrasp& g = bottle_demonstration();
  REQUIRE(g.stable());
  TransferOptions options;
  const SdhTransfer a = transfer(TransferMethod::autoclose, bottle, g, options);
  INFO(a.reason);
  REQUIRE(a.planned);
  CHECK(a.method == TransferMethod::autoclose);
  CHECK(a.sweeps == 0);
  CHECK(a.q_open == options.sdh_preshape);
  const Eigen::Isometry3d human = palm_frame(source_grasp(g));
  const Eigen::Isometry3d placed = palm_frame(HandGrasp<models::schunk_sdh>{a.hand_pose, a.q_open});
  CHECK((placed.linear() - human.linear()).norm() < 1e-9);
  const Vec3 along = placed.translation() - human.translation();
  const double depth = along.dot(human.linear().col(2));
  CHECK(depth <= 1e-9);
  CHECK((along - depth * human.linear().col(2)).norm() < 1e-9);
  CHECK(a.stability.shake().steps > 0);  // judged
  // The same placement by transfer_hand (any pair of hands) and by transfer_autoclose.
  CHECK(transfer_autoclose(bottle, g, options).hand_pose.isApprox(a.hand_pose, 1e-12));
  const auto any =
      transfer_hand<models::schunk_sdh>(TransferMethod::autoclose, bottle, source_grasp(g));
  CHECK(any.hand_pose.isApprox(a.hand_pose, 1e-12));
  // The transplant pairs the grasp centres instead and opens the hand further: another pose.
  const SdhTransfer t = transfer(TransferMethod::transplant, bottle, g, options);
  CHECK_FALSE(t.hand_pose.isApprox(a.hand_pose, 1e-6));
}

TEST_CASE(
    "human -> Allegro: the topological plan moves the windings toward the human's three "
    "largest, and the grasp is judged",
    "[any_hand][transfer]") {
  const GraspObject bottle = objects::bottle();
  const HumanGrasp& g = bottle_demonstration();
  REQUIRE(g.stable());
  check_topological_allegro(
      transfer_hand<models::allegro_hand>(TransferMethod::topological, bottle, source_grasp(g)), g);
  // The transplant baseline aims at no winding and plans nothing.
  const auto t =
      transfer_hand<models::allegro_hand>(TransferMethod::transplant, bottle, source_grasp(g));
  CHECK(t.method == TransferMethod::transplant);
  CHECK_FALSE(t.source_winding.has_value());
  CHECK(t.sweeps == 0);
}

TEST_CASE("SDH -> Allegro: a robot grasp is a source; two SDH curves give three targets",
          "[any_hand][transfer]") {
  const GraspObject bottle = objects::bottle();
  const HumanGrasp& g = bottle_demonstration();
  REQUIRE(g.stable());
  const SdhTransfer sdh = transfer(TransferMethod::transplant, bottle, g, TransferOptions{});
  REQUIRE(sdh.planned);
  const auto r =
      transfer_hand<models::allegro_hand>(TransferMethod::topological, bottle, source_grasp(sdh));
  INFO(r.reason);
  REQUIRE(r.source_winding.has_value());
  const Vec2 w =
      hand_windings<models::schunk_sdh>(bottle.centre_of_mass(), sdh.hand_pose, sdh.q_closed);
  const double hi = w.maxCoeff(), lo = w.minCoeff();
  CHECK(*r.source_winding == Vec3(hi, lo, lo));
  // The fingertip mapping from three fingers to four: the thumb and two fingers fitted (the fit
  // of three pairs), the Allegro's middle finger left to close with the hand.
  const SourceGrasp from_sdh = describe_source(source_grasp(sdh));
  REQUIRE(detail::fingertip_pairs<models::allegro_hand>(from_sdh).size() == 3);
  const auto f = transfer_hand<models::allegro_hand>(TransferMethod::fingertip, bottle, from_sdh);
  INFO(f.reason);
  CHECK(f.planned);
  CHECK(f.method == TransferMethod::fingertip);
  // The fewest pairs a source can give: a thumb and one finger (the human's index and thumb).
  const SourceGrasp human = describe_source(g);
  SourceGrasp pinch = human;
  pinch.digits = {human.digits[0], human.digits[static_cast<std::size_t>(human.thumb)]};
  pinch.thumb = 1;
  REQUIRE(detail::fingertip_pairs<models::allegro_hand>(pinch).size() == 2);
  const auto p = transfer_hand<models::allegro_hand>(TransferMethod::fingertip, bottle, pinch);
  INFO(p.reason);
  CHECK(p.planned);
}

TEST_CASE(
    "a source is data: describe_source keeps what the methods read, exactly as the model gives "
    "it",
    "[any_hand][source]") {
  const GraspObject bottle = objects::bottle();
  const HumanGrasp& g = bottle_demonstration();
  REQUIRE(g.stable());
  constexpr auto& H = models::human_hand;
  const HandGrasp<H> hand = source_grasp(g);
  const SourceGrasp s = describe_source(g);
  CHECK(unusable_source(s).empty());
  CHECK(s.hand == H.name.view());
  CHECK(s.root.matrix() == hand.root.matrix());
  CHECK(s.grasp_frame.matrix() == grasp_frame(hand).matrix());
  CHECK(s.palm_frame.matrix() == palm_frame(hand).matrix());
  CHECK(s.digits.size() == H.fingers.size());
  CHECK(s.thumb == H.thumb);
  CHECK(static_cast<int>(s.curves.size()) == hand_curve_count<H>);
  CHECK_FALSE(s.palm.empty());
  // The windings around any point are the model's, to the last bit.
  for (const Vec3& p :
       {bottle.centre_of_mass(), Vec3(s.grasp_frame.translation()), Vec3(0.3, -0.1, 0.2)}) {
    const Eigen::VectorXd w = source_windings(s, p);
    const Eigen::VectorXd v = hand_windings<H>(p, hand.root, hand.q);
    CHECK(w == v);
  }
  // The fingertips, digit lengths and palm shapes are the model's, to the last bit.
  KinematicsData<H> d;
  forward_kinematics(d, hand.q);
  for (int f = 0; f < static_cast<int>(H.fingers.size()); ++f) {
    const SourceDigit& digit = s.digits[static_cast<std::size_t>(f)];
    CHECK(digit.tip == world_point(d, finger_tip<H>(f)));
    CHECK(digit.length == detail::digit_length<H>(f));
  }
  std::size_t palm = 0;
  for (std::size_t k = 0; k < H.n_shapes; ++k) {
    if (H.shapes[k].link != H.palm.link) continue;
    REQUIRE(palm < s.palm.size());
    const Primitive model = world_shape(d, k);
    CHECK(s.palm[palm].R == model.R);
    CHECK(s.palm[palm].p == model.p);
    CHECK(s.palm[palm].size == model.size);
    ++palm;
  }
  CHECK(palm == s.palm.size());
  // A copy made field by field (as a reader of a file would make it) transfers as the grasp does.
  SourceGrasp copy;
  copy.hand = "a demonstrator this program does not know";
  copy.root = s.root;
  copy.grasp_frame = s.grasp_frame;
  copy.palm_frame = s.palm_frame;
  copy.curves = s.curves;
  copy.digits = s.digits;
  copy.thumb = s.thumb;
  copy.palm = s.palm;
  for (const TransferMethod m : {TransferMethod::transplant, TransferMethod::virtual_finger}) {
    const auto a = transfer_hand<models::allegro_hand>(m, bottle, hand);
    const auto b = transfer_hand<models::allegro_hand>(m, bottle, copy);
    CHECK(a.planned == b.planned);
    CHECK(a.reason == b.reason);
    CHECK(a.hand_pose.matrix() == b.hand_pose.matrix());
    CHECK(a.q_closed == b.q_closed);
    CHECK(a.stability.stable == b.stability.stable);
  }
}

TEST_CASE("a source that is not a usable hand is refused by every method with the reason",
          "[any_hand][source][errors]") {
  const GraspObject bottle = objects::bottle();
  const HumanGrasp& g = bottle_demonstration();
  REQUIRE(g.stable());
  const SourceGrasp good = describe_source(g);
  REQUIRE_FALSE(good.palm.empty());
  constexpr double nan = std::numeric_limits<double>::quiet_NaN();
  const std::pair<void (*)(SourceGrasp&), const char*> cases[] = {
      {[](SourceGrasp& s) { s.digits.resize(1); }, "the source hand has fewer than two fingers"},
      {[](SourceGrasp& s) { s.thumb = 7; }, "the source hand's thumb is not one of its fingers"},
      {[](SourceGrasp& s) { s.curves.clear(); },
       "the source hand has no curve to take windings of"},
      {[](SourceGrasp& s) { s.curves[0].resize(1); },
       "a curve of the source hand has fewer than two points"},
      {[](SourceGrasp& s) { s.curves[1][0].x() = nan; },
       "a curve of the source hand is not finite"},
      {[](SourceGrasp& s) { s.grasp_frame.translation().y() = nan; },
       "the source hand pose is not finite"},
      {[](SourceGrasp& s) { s.thumb = -1; }, "the source hand's thumb is not one of its fingers"},
      {[](SourceGrasp& s) { s.grasp_frame.linear() *= 2.0; },
       "a frame of the source hand is not a rigid transform"},
      {[](SourceGrasp& s) { s.digits[2].length = -0.01; },
       "a fingertip or digit length of the source hand is not finite, or a length below 0"},
      {[](SourceGrasp& s) { s.digits[1].length = nan; },
       "a fingertip or digit length of the source hand is not finite, or a length below 0"},
      {[](SourceGrasp& s) { s.digits[0].tip.z() = nan; },
       "a fingertip or digit length of the source hand is not finite, or a length below 0"},
      {[](SourceGrasp& s) { s.palm[0].p.x() = nan; },
       "a palm shape of the source hand is not finite, or has a size below 0"},
      {[](SourceGrasp& s) { s.palm[0].size.x() = -0.01; },
       "a palm shape of the source hand is not finite, or has a size below 0"},
  };
  for (const auto& [spoil, reason] : cases) {
    SourceGrasp bad = good;
    spoil(bad);
    INFO(reason);
    CHECK(unusable_source(bad) == reason);
    for (const TransferMethod m :
         {TransferMethod::topological, TransferMethod::autoclose, TransferMethod::transplant,
          TransferMethod::fingertip, TransferMethod::virtual_finger}) {
      const auto r = transfer_hand<models::allegro_hand>(m, bottle, bad);
      CHECK_FALSE(r.planned);
      CHECK(r.reason == reason);
    }
    CHECK_THROWS_WITH(fingertip_targets<models::allegro_hand>(bottle, bad),
                      std::string("source: ") + reason);
    CHECK_THROWS_WITH(fingertip_scale<models::allegro_hand>(bad), std::string("source: ") + reason);
  }
  CHECK(unusable_source(SourceGrasp{}) == "the source hand has fewer than two fingers");
  // Digits without length: every method but the fingertip mapping, which has no scale.
  SourceGrasp flat = good;
  for (SourceDigit& digit : flat.digits) digit.length = 0.0;
  CHECK(unusable_source(flat).empty());
  const auto no_scale =
      transfer_hand<models::allegro_hand>(TransferMethod::fingertip, bottle, flat);
  CHECK_FALSE(no_scale.planned);
  CHECK(no_scale.reason == "the source's fitted digits have no length (no fingertip scale)");
  CHECK(transfer_hand<models::allegro_hand>(TransferMethod::transplant, bottle, flat).planned);
  // The SDH's Table I fingertip targets of a human grasp that is not finite.
  HumanGrasp spoiled = g;
  spoiled.q[0] = nan;
  CHECK_THROWS_WITH(fingertip_targets(bottle, spoiled),
                    "source: the source configuration is not finite");
  // A grasp that is not finite: describe_source records why and takes nothing else.
  HandGrasp<models::human_hand> hand = source_grasp(g);
  hand.q[5] = nan;
  const SourceGrasp unusable = describe_source(hand);
  CHECK(unusable.unusable == "the source configuration is not finite");
  CHECK(unusable.curves.empty());
  CHECK(unusable_source(unusable) == "the source configuration is not finite");
  hand = source_grasp(g);
  hand.root.translation().z() = std::numeric_limits<double>::infinity();
  CHECK(unusable_source(describe_source(hand)) == "the source hand pose is not finite");
}

TEST_CASE("the fingertip correspondence: thumb to thumb, the fingers spread, each used once",
          "[any_hand]") {
  // Human fingers: index 0, middle 1, ring 2, little 3, thumb 4.
  using A3 = std::array<int, 3>;
  using A4 = std::array<int, 4>;
  using A5 = std::array<int, 5>;
  // The SDH (finger 1, finger 2, thumb): the index and the ring, as Table I's fingertip mapping.
  STATIC_REQUIRE(fingertip_correspondence<models::schunk_sdh, models::human_hand>() == A3{0, 2, 4});
  STATIC_REQUIRE(fingertip_correspondence<models::barrett_bh8, models::human_hand>() ==
                 A3{0, 2, 4});
  // The Allegro (index, middle, ring, thumb) and the Shadow hand (index ... little, thumb).
  STATIC_REQUIRE(fingertip_correspondence<models::allegro_hand, models::human_hand>() ==
                 A4{0, 1, 2, 4});
  STATIC_REQUIRE(fingertip_correspondence<models::shadow_hand, models::human_hand>() ==
                 A5{0, 1, 2, 3, 4});
  // More target fingers than source fingers: the extra ones are left out of the fit.
  STATIC_REQUIRE(fingertip_correspondence<models::allegro_hand, models::schunk_sdh>() ==
                 A4{0, -1, 1, 2});
  STATIC_REQUIRE(fingertip_correspondence<models::shadow_hand, models::allegro_hand>() ==
                 A5{0, -1, 1, 2, 3});
  STATIC_REQUIRE(fingertip_count<models::allegro_hand, models::schunk_sdh> == 3);
  // A source whose thumb is not its last finger: the others are counted around it.
  STATIC_REQUIRE(fingertip_correspondence<models::allegro_hand>(5, 0) == A4{1, 2, 3, 0});
  STATIC_REQUIRE(fingertip_correspondence<models::allegro_hand>(5, 2) == A4{0, 1, 3, 2});
  CHECK_THROWS_WITH(fingertip_correspondence<models::allegro_hand>(1, 0),
                    Catch::StartsWith("source_fingers: "));
  CHECK_THROWS_WITH(fingertip_correspondence<models::allegro_hand>(5, 5),
                    Catch::StartsWith("source_thumb: "));
  // The SDH/human size ratio of Table I (digits from their first own link out to the tip).
  CHECK(fingertip_scale<models::schunk_sdh, models::human_hand>() == Approx(2.175).epsilon(2e-3));
  CHECK(fingertip_scale<models::human_hand, models::schunk_sdh>() ==
        Approx(1.0 / 2.175).epsilon(2e-3));
}

TEST_CASE(
    "human -> Allegro by the fingertip and virtual-finger mappings: planned, judged, the "
    "tips on their targets",
    "[any_hand][transfer][baselines]") {
  const GraspObject bottle = objects::bottle();
  const HumanGrasp& g = bottle_demonstration();
  REQUIRE(g.stable());
  const auto tips = fingertip_targets<models::allegro_hand>(bottle, source_grasp(g));
  REQUIRE(tips.size() == 4);
  // Each target lies out of the object by the Allegro's tip radius and the contact gap.
  const Composite shape = bottle.composite();
  const GraspSimOptions sim;
  for (const Vec3& p : tips) {
    double distance = std::numeric_limits<double>::infinity();
    for (const Primitive& part : shape.parts())
      distance = std::min(distance, signed_distance(part, Primitive::sphere(p, 1e-9)).distance);
    CHECK(distance == Approx(0.012 + sim.contact_gap).margin(1e-6));
  }
  const auto f =
      transfer_hand<models::allegro_hand>(TransferMethod::fingertip, bottle, source_grasp(g));
  INFO(f.reason);
  REQUIRE(f.planned);
  CHECK(f.method == TransferMethod::fingertip);
  CHECK_FALSE(f.source_winding.has_value());
  CHECK(f.stability.weight > 0.0);
  CHECK((f.q_open.array() >= lower_limits<models::allegro_hand>().array()).all());
  CHECK((f.q_open.array() <= upper_limits<models::allegro_hand>().array()).all());
  const auto v =
      transfer_hand<models::allegro_hand>(TransferMethod::virtual_finger, bottle, source_grasp(g));
  INFO(v.reason);
  REQUIRE(v.planned);
  CHECK((v.reason == "pad opposition" || v.reason == "palm opposition"));
  CHECK(v.stability.weight > 0.0);
  // Palm opposition: the Allegro placed as the transplant, its approach the human's.
  if (v.reason == "palm opposition") {
    constexpr auto& a = models::allegro_hand;
    KinematicsData<a> d;
    forward_kinematics(d, v.q_open);
    const Vec3 approach =
        v.hand_pose.linear() * (d.frame_R[a.frame("palm_centre")] * Vec3::UnitZ());
    CHECK(approach.dot(grasp_frame(source_grasp(g)).linear().col(2)) == Approx(1.0).margin(1e-9));
  }
}

TEST_CASE("human -> Allegro on the arm: the paper's planner for any hand", "[any_hand][transfer]") {
  const GraspObject bottle = objects::bottle();
  const HumanGrasp& g = bottle_demonstration();
  REQUIRE(g.stable());
  check_topological_allegro(transfer_hand_on_arm<models::allegro_hand>(TransferMethod::topological,
                                                                       bottle, source_grasp(g)),
                            g);
  // The SDH on the arm from the human hand is Table I's transfer_topological: the same targets
  // (the human's two largest windings, to rounding) and the same plan.
  const auto sdh = transfer_hand_on_arm<models::schunk_sdh>(TransferMethod::topological, bottle,
                                                            source_grasp(g));
  const SdhTransfer table = transfer_topological(bottle, g);
  REQUIRE(sdh.planned);
  REQUIRE(table.planned);
  CHECK((*sdh.source_winding - g.descriptor.values).norm() < 1e-9);
  CHECK((sdh.hand_pose.translation() - table.hand_pose.translation()).norm() < 1e-3);
  // The baselines place the hand without the arm.
  for (const TransferMethod m :
       {TransferMethod::transplant, TransferMethod::fingertip, TransferMethod::virtual_finger})
    CHECK_THROWS_WITH(transfer_hand_on_arm<models::allegro_hand>(m, bottle, source_grasp(g)),
                      Catch::StartsWith("method: ") && Catch::Contains(std::string(to_string(m))));
  auto bad = source_grasp(g);
  bad.q[0] = std::numeric_limits<double>::quiet_NaN();
  const auto refused =
      transfer_hand_on_arm<models::allegro_hand>(TransferMethod::paper, bottle, bad);
  CHECK_FALSE(refused.planned);
  CHECK(refused.method == TransferMethod::paper);
  CHECK(refused.reason == "the source configuration is not finite");
}

TEST_CASE("transfer_hand: bad input is refused with a reason or an exception naming it",
          "[any_hand][errors]") {
  const GraspObject bottle = objects::bottle();
  const HumanGrasp& g = bottle_demonstration();
  REQUIRE(g.stable());
  auto source = source_grasp(g);
  source.root.translation().x() = std::numeric_limits<double>::infinity();
  for (const TransferMethod m :
       {TransferMethod::topological, TransferMethod::autoclose, TransferMethod::transplant,
        TransferMethod::fingertip, TransferMethod::virtual_finger}) {
    const auto r = transfer_hand<models::allegro_hand>(m, bottle, source);
    CHECK_FALSE(r.planned);
    CHECK(r.reason == "the source hand pose is not finite");
  }
  source = source_grasp(g);
  source.q[3] = std::numeric_limits<double>::quiet_NaN();
  CHECK(transfer_hand<models::allegro_hand>(TransferMethod::topological, bottle, source).reason ==
        "the source configuration is not finite");
  CHECK_THROWS_WITH(
      transfer_hand<models::allegro_hand>(TransferMethod::closed_windings, bottle, source_grasp(g)),
      Catch::StartsWith("method: ") && Catch::Contains("closed_windings"));
  CHECK_THROWS_WITH(transfer_hand<models::allegro_hand>(TransferMethod::shuffled_windings, bottle,
                                                        source_grasp(g)),
                    Catch::StartsWith("method: ") && Catch::Contains("shuffled_windings"));
  // A fingertip fit whose targets are far out of the hand's reach (a scale that transfer_hand's
  // option check would refuse first) is not planned, not reported.
  TransferOptions far;
  far.fingertip_scale = 1e10;
  const auto unreached = fingertip_grasp<models::allegro_hand>(bottle, source_grasp(g), far);
  CHECK_FALSE(unreached.planned);
  CHECK_THAT(unreached.reason, Catch::Contains("did not reach the targets"));
  TransferOptions bad;
  bad.backoff = -1.0;
  CHECK_THROWS_WITH(transfer_hand<models::allegro_hand>(TransferMethod::topological, bottle,
                                                        source_grasp(g), bad),
                    Catch::Contains("backoff"));
}
