// SPDX-License-Identifier: BSD-3-Clause
// A transfer method that cannot do its work says so (planned false, a reason), and never reports
// another method's pose as its result; a plan that makes no progress is judged at its start, as
// the no-plan control is (issue 29), and the shuffled-windings control aims at another's windings.
#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

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
  for (const TransferMethod m :
       {TransferMethod::fingertip, TransferMethod::autoclose, TransferMethod::transplant,
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

TEST_CASE("a fit that accepted no step is not reported as a transfer",
          "[grasp][transfer][bad-input]") {
  const GraspObject hammer = objects::hammer();
  // No iteration of the fingertip fit: it never leaves the transplant pose it starts from, which
  // used to be simulated and reported as the fingertip transfer.
  TransferOptions options;
  options.fingertip_iterations = 0;
  check_not_planned(transfer_fingertip(hammer, hammer_grasp(), options), TransferMethod::fingertip,
                    "the fingertip fit accepted no step");
}

TEST_CASE("a plan that makes no progress is judged at its start, as the no-plan control is",
          "[grasp][transfer][controls]") {
  // An AICO plan that accepts no sweep (one sweep allowed, and the first sweep only initialises)
  // leaves the hand at the plan's start: it is moved on until contact, closed and judged there
  // (issue 29: never counted unstable without a simulation), and the reason says so.
  const GraspObject hammer = objects::hammer();
  TransferOptions one_sweep;
  one_sweep.aico.max_sweeps = 1;
  const SdhTransfer stalled = transfer_topological(hammer, hammer_grasp(), one_sweep);
  INFO(stalled.reason);
  CHECK(std::none_of(stalled.sweep_log.begin(), stalled.sweep_log.end(),
                     [](const AicoSweepRecord& s) { return s.accepted; }));
  CHECK(stalled.planned);
  CHECK_THAT(stalled.reason, Catch::Contains("the plan made no progress (max_sweeps)") &&
                                 Catch::Contains("judged at its start"));
  CHECK(stalled.stability.shake().steps > 0);  // simulated
  // The no-plan control does not plan and is judged at the same start: the same grasp.
  const SdhTransfer none = transfer(TransferMethod::no_plan, hammer, hammer_grasp(), {});
  INFO(none.reason);
  CHECK(none.method == TransferMethod::no_plan);
  CHECK(none.planned);
  CHECK(none.sweeps == 0);
  CHECK_THAT(none.reason, Catch::Contains("no plan"));
  CHECK(none.hand_pose.isApprox(stalled.hand_pose, 1e-12));
  CHECK(none.q_open.isApprox(stalled.q_open, 1e-12));
  CHECK(none.stable() == stalled.stable());
  // The topological method itself plans, and ends elsewhere.
  const SdhTransfer planned = transfer_topological(hammer, hammer_grasp(), {});
  CHECK(planned.sweeps > 1);
  CHECK_FALSE(planned.hand_pose.isApprox(none.hand_pose, 1e-6));
}

TEST_CASE("the shuffled-windings control aims the plan at another demonstration's windings",
          "[grasp][transfer][controls]") {
  const GraspObject hammer = objects::hammer();
  const HumanGrasp& g = hammer_grasp();
  // Another demonstration of the hammer whose windings differ from g's.
  const std::vector<GraspHypothesis> hyps = box_hypotheses(hammer);
  const HumanGrasp other = demonstrate(hammer, hyps[40], 40);
  REQUIRE(other.reached);
  REQUIRE((other.descriptor.values - g.descriptor.values).norm() > 0.1);
  const SdhTransfer r = transfer_shuffled(hammer, g, &other, {});
  INFO(r.reason);
  CHECK(r.method == TransferMethod::shuffled_windings);
  REQUIRE(r.source_winding.has_value());
  CHECK(r.source_winding->isApprox(other.descriptor.values));
  // From the same start as the topological transfer of g (its grasp frame), toward other targets.
  const SdhTransfer own = transfer_topological(hammer, g, {});
  REQUIRE(own.source_winding.has_value());
  CHECK(own.source_winding->isApprox(g.descriptor.values));
  // Without another demonstration that reached the object: not planned, and it says why.
  check_not_planned(transfer_shuffled(hammer, g, nullptr, {}), TransferMethod::shuffled_windings,
                    "no other demonstration reached the object");
  HumanGrasp missed = other;
  missed.reached = false;
  check_not_planned(transfer_shuffled(hammer, g, &missed, {}), TransferMethod::shuffled_windings,
                    "no other demonstration reached the object");
}
