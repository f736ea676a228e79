// SPDX-License-Identifier: BSD-3-Clause
// A transfer method that cannot do its work says so (planned false, a reason), and never reports
// another method's pose, or its own starting pose, as its result.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <catch2/catch.hpp>

#include <topograsp/grasp/transfer.hpp>

using namespace topograsp;

namespace {

// The hand-picked hammer grasp of test_experiment.cpp: a power grasp of the handle.
const HumanGrasp& hammer_grasp() {
  static const HumanGrasp g = [] {
    const GraspObject hammer = objects::hammer();
    return demonstrate(hammer, box_hypotheses(hammer)[26], 26);
  }();
  return g;
}

void check_not_planned(const SdhTransfer& r, TransferMethod method, const std::string& why) {
  INFO(r.reason);
  CHECK(r.method == method);
  CHECK_FALSE(r.planned);
  CHECK_FALSE(r.stable());
  CHECK_THAT(r.reason, Catch::Contains(why));
  // Nothing was simulated: the result does not carry a pose of any method.
  CHECK(r.hand_pose.isApprox(Eigen::Isometry3d::Identity(), 0.0));
  CHECK(r.q_closed.isZero(0.0));
}

}  // namespace

TEST_CASE("a fingertip fit whose cost overflows is not reported as a fingertip transfer",
          "[grasp][transfer][bad-input]") {
  // fingertip_scale = 1e300: the targets' squared errors overflow, the fit never accepted a step,
  // and the transplant pose it starts from used to be simulated and reported as the fingertip
  // transfer (planned, shaken, possibly "stable").
  const GraspObject hammer = objects::hammer();
  TransferOptions options;
  options.fingertip_scale = 1e300;
  const SdhTransfer r = transfer_fingertip(hammer, hammer_grasp(), options);
  check_not_planned(r, TransferMethod::fingertip, "fingertip fit's cost is not finite");
  CHECK_THAT(r.reason, Catch::Contains("1e+300"));
  // Scales whose cost is finite but whose targets are out of the hand's reach: the fit ends
  // with its tips far from them (the free base reaches 10 m), and that is not a fingertip grasp.
  for (const double scale : {1e3, 1e120}) {
    options.fingertip_scale = scale;
    const SdhTransfer far = transfer_fingertip(hammer, hammer_grasp(), options);
    INFO("scale " << scale << ": " << far.reason);
    check_not_planned(far, TransferMethod::fingertip, "the fingertip fit");
    CHECK((far.reason.find("did not reach the targets") != std::string::npos ||
           far.reason.find("accepted no step") != std::string::npos));
  }
  // The default scale still plans.
  const SdhTransfer ok = transfer_fingertip(hammer, hammer_grasp(), TransferOptions{});
  CHECK(ok.planned);
}

TEST_CASE("a human grasp with NaN is refused by every method in its result",
          "[grasp][transfer][bad-input]") {
  const GraspObject hammer = objects::hammer();
  HumanGrasp bad_q = hammer_grasp();
  bad_q.q[5] = std::numeric_limits<double>::quiet_NaN();
  HumanGrasp bad_pose = hammer_grasp();
  bad_pose.hand_pose.translation().x() = std::numeric_limits<double>::quiet_NaN();
  const TransferOptions options;
  for (const TransferMethod m : {TransferMethod::fingertip, TransferMethod::transplant,
                                 TransferMethod::virtual_finger, TransferMethod::topological}) {
    CAPTURE(to_string(m));
    check_not_planned(transfer(m, hammer, bad_q, options), m,
                      "the human configuration is not finite");
    check_not_planned(transfer(m, hammer, bad_pose, options), m,
                      "the human hand pose is not finite");
  }
}

TEST_CASE("a human grasp with NaN windings is refused, not planned toward",
          "[grasp][transfer][bad-input]") {
  const GraspObject hammer = objects::hammer();
  HumanGrasp g = hammer_grasp();
  g.descriptor.values[0] = std::numeric_limits<double>::quiet_NaN();
  const SdhTransfer r = transfer_topological(hammer, g, TransferOptions{});
  check_not_planned(r, TransferMethod::topological, "the human windings are not finite");
}

TEST_CASE("a fit or a plan that accepted no step is not reported as a transfer",
          "[grasp][transfer][bad-input]") {
  const GraspObject hammer = objects::hammer();
  // No iteration of the fingertip fit: it never leaves the transplant pose it starts from, which
  // used to be simulated and reported as the fingertip transfer.
  TransferOptions options;
  options.fingertip_iterations = 0;
  check_not_planned(transfer_fingertip(hammer, hammer_grasp(), options), TransferMethod::fingertip,
                    "the fingertip fit accepted no step");
  // An AICO plan that accepts no sweep (one sweep allowed, and the first sweep only initialises)
  // is the ready pose held still: not a topological transfer, whatever ended the plan.
  TransferOptions one_sweep;
  one_sweep.aico.max_sweeps = 1;
  const SdhTransfer r = transfer_topological(hammer, hammer_grasp(), one_sweep);
  CHECK(std::none_of(r.sweep_log.begin(), r.sweep_log.end(),
                     [](const AicoSweepRecord& s) { return s.accepted; }));
  // It ended on max_sweeps, not on non-finite values, and used to be simulated as the transfer.
  check_not_planned(r, TransferMethod::topological, "the plan failed before any progress");
  CHECK_THAT(r.reason, Catch::Contains("max_sweeps"));
}
