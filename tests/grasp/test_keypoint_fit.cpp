// SPDX-License-Identifier: BSD-3-Clause
// fit_human_hand (grasp/keypoint_fit.hpp): the keypoints of a known human hand grasp fitted back
// to the model, and what the fit does with bad input.
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

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
  INFO("rms " << fit.rms_error << " m, max " << fit.max_error << " m, " << fit.iterations
              << " steps");
  CHECK(fit.max_error < 1e-3);
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
  CHECK_THROWS_WITH(fit_human_hand(KeypointGrasp{}, -1), Catch::StartsWith("iterations: "));
}
