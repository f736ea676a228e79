// SPDX-License-Identifier: BSD-3-Clause
// fit_human_hand (grasp/keypoint_fit.hpp): the keypoints of a known human hand grasp fitted back
// to the model, and what the fit does with bad input.
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <catch2/catch.hpp>

#include <topograsp/grasp/hypothesis.hpp>
#include <topograsp/grasp/keypoint_fit.hpp>

using namespace topograsp;

TEST_CASE("the human model's own keypoints are fitted back to within a millimetre",
          "[grasp][keypoints]") {
  constexpr auto& h = models::human_hand;
  HandGrasp<h> truth;
  truth.root.linear() =
      (Eigen::AngleAxisd(0.7, Vec3::UnitZ()) * Eigen::AngleAxisd(-0.4, Vec3::UnitY()))
          .toRotationMatrix();
  truth.root.translation() = Vec3(0.05, -0.12, 0.2);
  // A closed power grasp: every joint 60 % of the way from its lower to its upper limit.
  truth.q = lower_limits<h>() + 0.6 * (upper_limits<h>() - lower_limits<h>());
  const KeypointGrasp k = human_keypoints(truth, "bottle");
  const KeypointFit fit = fit_human_hand(k);
  INFO("rms " << fit.error.rms << " m, max " << fit.error.max << " m, " << fit.iterations
              << " steps");
  CHECK(fit.error.max < 1e-3);
  const KeypointGrasp back = human_keypoints(fit.grasp, "bottle");
  for (int i = 0; i < keypoint_count; ++i)
    CHECK((back.keypoints[static_cast<std::size_t>(i)] - k.keypoints[static_cast<std::size_t>(i)])
              .norm() < 1e-3);
  CHECK((fit.grasp.q.array() >= lower_limits<h>().array() - 1e-12).all());
  CHECK((fit.grasp.q.array() <= upper_limits<h>().array() + 1e-12).all());
  // The windings from the keypoints and from the fitted model agree in sign and roughly in size
  // (the keypoint curves' palm point is the centroid of the wrist and the MCPs, not the model's).
  const Vec3 p = truth.root * Vec3(0.04, 0.0, 0.12);
  const Eigen::Vector4d wk = keypoint_windings(k, p);
  const Eigen::Vector4d wm = hand_windings<h>(p, truth.root, truth.q);
  INFO("keypoints " << wk.transpose() << ", model " << wm.transpose());
  CHECK((wk - wm).cwiseAbs().maxCoeff() < 0.1);
}

TEST_CASE("fit_human_hand refuses keypoints that are not finite", "[grasp][keypoints][bad-input]") {
  KeypointGrasp k;
  k.keypoints[3].y() = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_WITH(fit_human_hand(k), Catch::StartsWith("keypoints: "));
  // A grasp not yet set has its keypoints at the origin (finite): only the iterations are bad.
  CHECK(KeypointGrasp{}.keypoints[20] == Vec3::Zero());
  CHECK_THROWS_WITH(fit_human_hand(KeypointGrasp{}, -1), Catch::StartsWith("iterations: "));
}

TEST_CASE("a recorded grasp is a demonstration: the keypoints of a planned one give it back",
          "[grasp][keypoints][demonstration]") {
  // The bottle's first stable planned demonstration, recorded as its 21 keypoints, fitted,
  // opened, placed and closed again: reached, judged, its windings those of the planned one.
  const GraspObject bottle = objects::bottle();
  const std::vector<GraspHypothesis> hyps = box_hypotheses(bottle);
  std::optional<HumanGrasp> planned;
  for (int i = 0; i < static_cast<int>(hyps.size()) && !planned; ++i) {
    HumanGrasp g = demonstrate(bottle, hyps[static_cast<std::size_t>(i)], i);
    if (g.stable()) planned = std::move(g);
  }
  REQUIRE(planned.has_value());
  const KeypointGrasp recorded = human_keypoints(source_grasp(*planned), "bottle");
  KeypointFit fit;
  const HumanGrasp g = demonstrate_recorded(bottle, recorded, 7, {}, &fit);
  CHECK(fit.error.max < 1e-3);
  // The fit's error goes with the demonstration (results.json's fit_error); a planned one
  // has none.
  REQUIRE(g.fit_error);
  CHECK(g.fit_error->rms == fit.error.rms);
  CHECK(g.fit_error->max == fit.error.max);
  CHECK_FALSE(planned->fit_error);
  CHECK(g.id == 7);
  CHECK(g.hypothesis.box == -1);
  REQUIRE(g.reached);
  INFO("planned " << planned->windings.transpose() << ", recorded " << g.windings.transpose());
  CHECK((g.windings - planned->windings).cwiseAbs().maxCoeff() < 0.15);
  CHECK(g.stable());
  // The palm ends where the recording put it, within the opening and the approach (a few cm).
  CHECK((g.hand_pose.translation() - planned->hand_pose.translation()).norm() < 0.03);
}

TEST_CASE("demonstrate_recorded refuses a recording of another object",
          "[grasp][keypoints][bad-input]") {
  HandGrasp<models::human_hand> pose;
  pose.root.translation() = Vec3(-0.1, 0.0, 0.1);
  const KeypointGrasp k = human_keypoints(pose, "hammer");
  CHECK_THROWS_WITH(demonstrate_recorded(objects::bottle(), k, 0),
                    Catch::StartsWith("recorded.object: ") && Catch::Contains("\"hammer\""));
}
