// SPDX-License-Identifier: BSD-3-Clause
// The transfer methods by name: the topological method's named variants are the topological
// planner with some options switched, and run as such.
#include <string>

#include <catch2/catch.hpp>

#include <topograsp/grasp/transfer.hpp>

using namespace topograsp;

TEST_CASE("every transfer method is found by its name, and no other name",
          "[grasp][transfer][methods]") {
  for (const TransferMethod m : all_transfer_methods) {
    INFO(to_string(m));
    CHECK(transfer_method(to_string(m)) == m);
    CHECK(is_topological(m) ==
          (m != TransferMethod::autoclose && m != TransferMethod::transplant &&
           m != TransferMethod::fingertip && m != TransferMethod::virtual_finger));
  }
  CHECK_THROWS_WITH(transfer_method("papers"),
                    Catch::StartsWith("method: unknown method \"papers\" (expected topological, "
                                      "autoclose, transplant, fingertip, virtual_finger, paper,") &&
                        Catch::EndsWith("closed_windings, no_plan or shuffled_windings)"));
}

TEST_CASE("each variant switches exactly its parts of the topological method",
          "[grasp][transfer][methods]") {
  TransferOptions given;
  given.backoff = 0.05;  // kept by every variant
  const auto check_kept = [&](const TransferOptions& o) {
    CHECK(o.backoff == 0.05);
    CHECK(o.collision_precision == given.collision_precision);
    CHECK(o.approach_precision_end == given.approach_precision_end);
  };
  const auto line_on = [](const TransferOptions& o) {
    return o.line_precision_mid > 0.0 && o.line_precision_end > 0.0;
  };
  const auto windings_on = [](const TransferOptions& o) {
    return o.winding_precision_mid > 0.0 && o.winding_precision_end > 0.0;
  };
  for (const TransferMethod m :
       {TransferMethod::topological, TransferMethod::transplant, TransferMethod::fingertip,
        TransferMethod::virtual_finger, TransferMethod::shuffled_windings}) {
    const TransferOptions o = transfer_method_options(m, given);
    CHECK(o.plan);
    CHECK(o.closing_corrections == 0);
    check_kept(o);
    CHECK(line_on(o));
    CHECK(o.final_approach == given.final_approach);
    CHECK(windings_on(o));
    CHECK(o.winding_reference == WindingReference::centre_of_mass);
  }
  const TransferOptions paper = transfer_method_options(TransferMethod::paper, given);
  check_kept(paper);
  CHECK_FALSE(line_on(paper));
  CHECK(paper.line_precision_mid == 0.0);
  CHECK(paper.final_approach == 0.0);
  CHECK(windings_on(paper));
  CHECK(paper.winding_reference == WindingReference::centre_of_mass);
  const TransferOptions line = transfer_method_options(TransferMethod::paper_line, given);
  CHECK(line_on(line));
  CHECK(line.final_approach == 0.0);
  const TransferOptions approach = transfer_method_options(TransferMethod::paper_approach, given);
  CHECK_FALSE(line_on(approach));
  CHECK(approach.final_approach == given.final_approach);
  const TransferOptions none = transfer_method_options(TransferMethod::no_windings, given);
  check_kept(none);
  CHECK(none.winding_precision_mid == 0.0);
  CHECK(none.winding_precision_end == 0.0);
  CHECK(line_on(none));
  const TransferOptions nearest = transfer_method_options(TransferMethod::nearest_point, given);
  CHECK(nearest.winding_reference == WindingReference::nearest_point);
  CHECK(windings_on(nearest));
  const TransferOptions closed = transfer_method_options(TransferMethod::closed_windings, given);
  check_kept(closed);
  CHECK(closed.closing_corrections == 2);
  CHECK(line_on(closed));
  CHECK(windings_on(closed));
  CHECK(closed.plan);
  // The no-plan control: everything kept, only the plan skipped.
  const TransferOptions no_plan = transfer_method_options(TransferMethod::no_plan, given);
  check_kept(no_plan);
  CHECK_FALSE(no_plan.plan);
  CHECK(line_on(no_plan));
  CHECK(windings_on(no_plan));
  CHECK(no_plan.final_approach == given.final_approach);
}

TEST_CASE("a variant runs the topological planner with its options and says which it was",
          "[grasp][transfer][methods]") {
  const GraspObject hammer = objects::hammer();
  const HumanGrasp g = demonstrate(hammer, box_hypotheses(hammer)[22], 22);
  REQUIRE(g.stable());
  const TransferOptions options;
  const SdhTransfer by_name = transfer(TransferMethod::paper, hammer, g, options);
  const SdhTransfer by_hand =
      transfer_topological(hammer, g, transfer_method_options(TransferMethod::paper, options));
  CHECK(by_name.method == TransferMethod::paper);
  CHECK(by_hand.method == TransferMethod::topological);
  CHECK(by_name.planned == by_hand.planned);
  CHECK(by_name.sweeps == by_hand.sweeps);
  CHECK((by_name.hand_pose.matrix() - by_hand.hand_pose.matrix()).norm() == 0.0);
  CHECK(by_name.stable() == by_hand.stable());
}

TEST_CASE("the transplant opens the SDH by transplant_opening", "[grasp][transfer][methods]") {
  TransferOptions options;
  CHECK(options.transplant_opening == 0.7);
  options.transplant_opening = 0.3;  // sdh_preshape's opening
  CHECK(transplant_preshape(options) == options.sdh_preshape);
  options.transplant_opening = 0.7;
  options.sdh_preshape[0] = 0.1;
  const Vec<7> q = transplant_preshape(options);
  CHECK(q[0] == 0.1);
  for (const int i : {1, 3, 5}) {
    CHECK(q[i] == -0.7);
    CHECK(q[i + 1] == 0.7);
  }
  CHECK_THROWS_WITH(set_transfer_parameter(options, "transplant_opening", 2.0),
                    Catch::StartsWith("transplant_opening: must be in [0, 1.5]"));
}
