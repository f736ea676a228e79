// SPDX-License-Identifier: BSD-3-Clause
#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <catch2/catch.hpp>

#include <grasp_transfer/experiment.hpp>
#include <grasp_transfer/journal.hpp>
#include <grasp_transfer/results.hpp>
#include <topograsp/io/json_schema.hpp>
#include <topograsp/io/ycb_objects.hpp>

using namespace topograsp;

namespace {

ExperimentOptions small_options(int jobs) {
  ExperimentOptions c;
  c.objects = {objects::hammer(), objects::bottle()};
  c.methods = {TransferMethod::topological, TransferMethod::transplant, TransferMethod::fingertip};
  c.jobs = jobs;
  c.seed = 7;
  c.max_hypotheses = 4;  // a few grasps per object: the sanitizer build runs this too
  return c;
}

// Four hypotheses of each object (ids 4, 22, 40, 58) among which both objects have stable
// demonstrations under the stability suite (the first four of the bottle have none: the squeeze
// overlaps it by more than 1 cm, or it slides out with gravity along +x of the hand).
ExperimentOptions stable_options(int jobs) {
  ExperimentOptions c = small_options(jobs);
  c.max_hypotheses = 0;
  c.shard_index = 4;
  c.shard_count = 18;
  return c;
}

bool is_integer(const Json& j) {
  return j.is_number() && j.as_number() == std::floor(j.as_number());
}

}  // namespace

TEST_CASE("a small experiment: counts, schema and determinism", "[grasp][experiment][end_to_end]") {
  const ExperimentOptions config = stable_options(2);
  const std::vector<ObjectResult> results = run_experiment(config);
  REQUIRE(results.size() == 2);
  for (const ObjectResult& r : results) {
    INFO(r.object.name);
    CHECK(r.hypotheses == 4);
    CHECK(r.human.size() == 4);
    int stable = 0;
    for (const HumanGrasp& g : r.human) stable += g.stable() ? 1 : 0;
    CHECK(r.stable_human() == stable);
    CHECK(stable > 0);  // so that every method is exercised
    REQUIRE(r.methods.size() == 3);
    for (std::size_t m = 0; m < 3; ++m) {
      CHECK(r.methods[m].tested == stable);
      CHECK(r.methods[m].stable <= r.methods[m].tested);
      CHECK(r.transfers[m].size() == static_cast<std::size_t>(stable));
      const std::vector<bool> v = method_outcomes(r, m, false);
      CHECK(std::count(v.begin(), v.end(), true) == r.methods[m].stable);
      CHECK(method_outcomes(r, m, true) == std::vector<bool>(v.size(), false));  // no 2nd judge
    }
    CHECK_THROWS_WITH(method_outcomes(r, 3, false), Catch::Contains("method index below 3"));
  }

  SECTION("results.json follows the documented schema") {
    const Json doc = Json::parse(results_json(config, results).dump(2));
    // The schema shipped with the library (data/schemas/results.schema.json), by version.
    const Json schema = Json::parse(
        detail::read_text_file(data_directory() + "/schemas/results.schema.json", "schema"));
    CHECK(validate_json(doc, schema).empty());
    CHECK(doc.at("schema_version").as_number() == results_schema_version);
    CHECK(schema.at("properties").at("schema_version").at("const").as_number() ==
          results_schema_version);
    // A record that breaks it is found, and where.
    Json broken = doc;
    const_cast<Json::Array&>(broken.at("grasps").as_array())[0].set("stable", "yes");
    CHECK_FALSE(validate_json(broken, schema).empty());
    CHECK_THAT(validate_json(broken, schema).front(), Catch::StartsWith("/grasps/0: "));
    REQUIRE(doc.at("config").is_object());
    CHECK(doc.at("config").at("objects").as_array().size() == 2);
    CHECK(doc.at("config").at("methods").as_array().size() == 3);
    CHECK(doc.at("config").at("setting").as_string() == "hand");
    const auto& objects = doc.at("objects").as_array();
    REQUIRE(objects.size() == 2);
    std::size_t expected_grasps = 0;
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const Json& o = objects[i];
      CHECK(o.at("name").as_string() == results[i].object.name);
      CHECK(is_integer(o.at("hypotheses")));
      CHECK(o.at("stable_human").as_number() == results[i].stable_human());
      CHECK(o.at("human").at("stable").as_number() == results[i].stable_human());
      for (const char* m : {"human", "topological", "transplant", "fingertip"}) {
        const Json& s = m == std::string("human") ? o.at("human") : o.at("methods").at(m);
        CHECK(is_integer(s.at("tested")));
        CHECK(is_integer(s.at("stable")));
        const double rate = s.at("rate").as_number();
        CHECK(rate >= 0.0);
        CHECK(rate <= 1.0);
        for (std::size_t t = 0; t < k_stability_tests; ++t) {
          // Over the grasps that ran the test; null when none did (the suite stops at a
          // grasp's first failure), and then no grasp is stable.
          const Json& p =
              s.at("test_pass_rate").at(std::string(to_string(static_cast<StabilityTest>(t))));
          if (p.is_null()) {
            CHECK(s.at("stable").as_number() == 0.0);
            continue;
          }
          const double pass = p.as_number();
          CHECK(pass >= 0.0);
          CHECK(pass <= 1.0);
          if (t + 1 < k_stability_tests) CHECK(pass >= rate);  // stable needs every test but one
        }
        const Json& ratio = s.at("median_force_ratio_stable");
        CHECK((ratio.is_null() ? s.at("stable").as_number() == 0.0 : ratio.as_number() > 0.0));
        // The rate's 95 % Wilson interval holds the rate.
        const auto& interval = s.at("interval").as_array();
        REQUIRE(interval.size() == 2);
        CHECK(interval[0].as_number() <= rate);
        CHECK(interval[1].as_number() >= rate);
        CHECK(interval[0].as_number() >= 0.0);
        CHECK(interval[1].as_number() <= 1.0);
      }
      // Each method against the topological one on the same grasps: the four kinds of pair add
      // up to the grasps tested, and the counts give the rates; no second judge here.
      CHECK(o.at("methods").at("topological").at("paired").is_null());
      const double topological_stable = o.at("methods").at("topological").at("stable").as_number();
      for (const char* m : {"transplant", "fingertip"}) {
        const Json& s = o.at("methods").at(m);
        const Json& p = s.at("paired");
        CHECK(p.at("against").as_string() == "topological");
        const double both = p.at("both").as_number(), only_this = p.at("only_this").as_number(),
                     only_against = p.at("only_against").as_number();
        CHECK(both + only_this + only_against + p.at("neither").as_number() ==
              s.at("tested").as_number());
        CHECK(both + only_this == s.at("stable").as_number());
        CHECK(both + only_against == topological_stable);
        CHECK(p.at("p_value").as_number() ==
              Approx(mcnemar_exact_p(static_cast<int>(only_this), static_cast<int>(only_against))));
        // The power to tell 15 points apart on these pairs, at their disagreement (at least 15 %).
        const double tested = s.at("tested").as_number();
        CHECK(
            p.at("power_15").as_number() ==
            Approx(mcnemar_exact_power(static_cast<int>(tested),
                                       std::max(0.15, (only_this + only_against) / tested), 0.15)));
        CHECK(s.at("paired_second").is_null());
      }
      for (const HumanGrasp& g : results[i].human) expected_grasps += g.reached ? 1 : 0;
      expected_grasps += 3 * static_cast<std::size_t>(results[i].stable_human());
    }
    // Over all objects: the counts add up, the intervals and paired tests are of the sums.
    const Json& overall = doc.at("overall");
    CHECK(overall.at("name").as_string() == "all objects");
    CHECK(overall.at("hypotheses").as_number() ==
          objects[0].at("hypotheses").as_number() + objects[1].at("hypotheses").as_number());
    CHECK(overall.at("stable_human").as_number() ==
          results[0].stable_human() + results[1].stable_human());
    for (const char* m : {"topological", "transplant", "fingertip"}) {
      const auto sum = [&](const char* field) {
        return objects[0].at("methods").at(m).at(field).as_number() +
               objects[1].at("methods").at(m).at(field).as_number();
      };
      const Json& s = overall.at("methods").at(m);
      CHECK(s.at("tested").as_number() == sum("tested"));
      CHECK(s.at("stable").as_number() == sum("stable"));
      const RateInterval w =
          wilson_interval(static_cast<int>(sum("stable")), static_cast<int>(sum("tested")));
      CHECK(s.at("interval").as_array()[0].as_number() == Approx(w.lower));
      CHECK(s.at("interval").as_array()[1].as_number() == Approx(w.upper));
      if (std::string(m) == "topological") continue;
      const auto pairs = [&](const char* field) {
        return static_cast<int>(objects[0].at("methods").at(m).at("paired").at(field).as_number() +
                                objects[1].at("methods").at(m).at("paired").at(field).as_number());
      };
      CHECK(s.at("paired").at("only_this").as_number() == pairs("only_this"));
      CHECK(s.at("paired").at("only_against").as_number() == pairs("only_against"));
      CHECK(s.at("paired").at("p_value").as_number() ==
            Approx(mcnemar_exact_p(pairs("only_this"), pairs("only_against"))));
    }
    const auto& grasps = doc.at("grasps").as_array();
    CHECK(grasps.size() == expected_grasps);
    // Paired: the demonstration and every method's transfer of it meet the same shakes.
    for (const Json& g : grasps) {
      const std::string seed = g.at("shake_seed").as_string();
      CHECK(seed == std::to_string(grasp_seed(config.seed, g.at("object").as_string(),
                                              static_cast<int>(g.at("id").as_number()))));
    }
    for (const Json& g : grasps) {
      CHECK(g.at("object").is_string());
      CHECK(is_integer(g.at("id")));
      CHECK(g.at("method").is_string());
      CHECK(g.at("stable").is_bool());
      CHECK((g.at("scene").is_string() || g.at("scene").is_null()));
      if (g.at("scene").is_string()) CHECK(g.at("scene").as_string().rfind("scenes/", 0) == 0);
      CHECK(g.at("winding_human").is_array());
      CHECK(g.at("winding_robot").is_array());
      CHECK(g.at("plan_ms").is_number());
      CHECK(is_integer(g.at("sweeps")));
      // What the planner said: AICO's termination for a planned topological transfer.
      if (g.at("method").as_string() == "topological" && g.at("scene").is_string())
        CHECK(g.at("planner").is_string());
      else if (g.at("method").as_string() == "human")
        CHECK_FALSE(g.contains("planner"));
      else
        CHECK((g.at("planner").is_null() || g.at("planner").is_string()));
      // The arm's joints only in the arm setting (--setting arm).
      if (g.at("method").as_string() != "human") CHECK(g.at("arm_joints").is_null());
      // What a robot executes: a placed transfer's configurations by the SDH's joint names, and
      // the topological plan whose last step puts the hand at the pre-grasp.
      if (g.at("method").as_string() != "human" && g.at("scene").is_string()) {
        const Json& c = g.at("configurations");
        for (const char* which : {"pregrasp", "grasp", "closed"}) {
          const auto& joints = c.at(which).at("joints").as_object();
          REQUIRE(joints.size() == 7u);
          for (int i = 0; i < 7; ++i)
            CHECK(joints[static_cast<std::size_t>(i)].first == models::schunk_sdh.joint_name(i));
        }
        const bool planned = g.at("method").as_string() == "topological";
        CHECK(g.at("motion").is_null() != planned);
        CHECK(g.at("object_pose").is_null() != planned);
        if (planned) {
          constexpr auto& A = OnArm<models::schunk_sdh>::model;
          const Json& m = g.at("motion");
          CHECK(m.at("q").as_array().size() == 41u);
          CHECK(m.at("time_step").as_number() == Approx(2.0 / 40));
          REQUIRE(m.at("joints").as_array().size() == 14u);
          CHECK(m.at("joints").as_array()[0].as_string() == "arm_1");
          Vec<14> q_end = detail::numbers(m.at("q").as_array().back(), 14, "q");
          KinematicsData<A> d;
          forward_kinematics(d, q_end);
          const Eigen::Isometry3d root =
              detail::pose_of(m.at("object_pose")).inverse() *
              link_pose(d, A.find_link(models::schunk_sdh.links[0].spec.name.view()));
          const Eigen::Isometry3d pre = detail::pose_of(c.at("pregrasp").at("hand_pose"));
          CHECK((root.translation() - pre.translation()).norm() < 1e-6);
          CHECK((root.linear() - pre.linear()).norm() < 1e-6);
        }
      }
      // Every test's record when the grasp was simulated; stable iff all but the hard shake
      // passed, and then the reason is empty.
      const auto& tests = g.at("tests").as_array();
      CHECK(tests.size() == (g.at("scene").is_string() ? k_stability_tests : 0));
      bool all = !tests.empty();
      for (std::size_t t = 0; t < tests.size(); ++t) {
        const Json& r = tests[t];
        CHECK(r.at("name").as_string() == to_string(static_cast<StabilityTest>(t)));
        // A test not run (the suite stopped at an earlier failure) measured nothing: null.
        const bool run = r.at("steps").as_number() > 0;
        CHECK(run == !r.at("reason").as_string().starts_with("not run"));
        for (const char* f :
             {"translation", "rotation", "force_median", "force_end", "force_ratio", "penetration"})
          CHECK((run ? r.at(f).is_number() || r.at(f).is_null() : r.at(f).is_null()));
        CHECK((run ? is_integer(r.at("contacts")) : r.at("contacts").is_null()));
        CHECK(is_integer(r.at("steps")));
        CHECK((run ? r.at("status").is_string() : r.at("status").is_null()));
        CHECK(r.at("reason").as_string().empty() == r.at("passed").as_bool());
        if (t + 1 < tests.size()) all = all && r.at("passed").as_bool();
      }
      CHECK(g.at("stable").as_bool() == all);
      if (!tests.empty()) {
        CHECK(g.at("weight").as_number() > 0.0);
        CHECK(g.at("closing_penetration").as_number() >= 0.0);
      }
      if (g.at("stable").as_bool()) CHECK(g.at("reason").as_string().empty());
      // What closing did: as many contact points as it counts, each on a named link, its
      // normal a unit vector, its force not negative; none, and the reason says so.
      const Json& closing = g.at("closing");
      if (closing.is_null()) continue;
      if (closing.at("contacts").as_number() == 0.0 && !g.at("stable").as_bool())
        CHECK_THAT(g.at("reason").as_string(),
                   Catch::StartsWith("closing ended with no contact; "));
      const auto& points = closing.at("contact_points").as_array();
      CHECK(static_cast<double>(points.size()) == closing.at("contacts").as_number());
      for (const Json& p : points) {
        CHECK_FALSE(p.at("link").as_string().empty());
        CHECK(p.at("point").as_array().size() == 3);
        const auto& n = p.at("normal").as_array();
        REQUIRE(n.size() == 3);
        CHECK(std::hypot(n[0].as_number(), n[1].as_number(), n[2].as_number()) == Approx(1.0));
        CHECK(p.at("force").as_number() >= 0.0);
      }
      // The motors' holding torques, one per joint of the grasp's hand (the human's 20, the
      // SDH's 7); uniform here (free closing), so not balanced and no imbalance.
      CHECK(closing.at("hold_torque").as_array().size() ==
            (g.at("method").as_string() == "human" ? 20u : 7u));
      CHECK_FALSE(closing.at("balanced_hold").as_bool());
      CHECK(closing.at("hold_imbalance").as_number() == 0.0);
    }
  }

  SECTION("same seed, same results, whatever the number of threads") {
    ExperimentOptions one = stable_options(1);
    const std::vector<ObjectResult> again = run_experiment(one);
    one.jobs = 2;  // the config records jobs; compare everything else
    Json a = results_json(one, again), b = results_json(config, results);
    for (Json* doc : {&a, &b})
      for (Json& g : const_cast<Json::Array&>(doc->at("grasps").as_array())) g.set("plan_ms", 0.0);
    CHECK(a.dump(0) == b.dump(0));
  }
}

TEST_CASE("close_human_grasp gives the scene demonstrate judges, or nothing on a miss",
          "[grasp][demonstrate]") {
  const GraspObject hammer = objects::hammer();
  const auto hyps = box_hypotheses(hammer);
  const HumanGrasp g = demonstrate(hammer, hyps[47], 47);
  const auto closed = close_human_grasp(hammer, hyps[47]);
  REQUIRE(closed.has_value());
  CHECK(closed->closing.q_closed == g.q);
  CHECK(closed->scene.hand_pose().isApprox(g.hand_pose, 1e-12));
  CHECK(closed->scene.object_pose().isApprox(g.object_pose, 1e-12));
  CHECK(closed->scene.hand_contacts() > 0);
  // The same hypothesis 1 m to the side: the approach passes the hammer by.
  GraspHypothesis miss = hyps[47];
  miss.centre += 1.0 * miss.up.cross(miss.approach);
  CHECK_FALSE(close_human_grasp(hammer, miss).has_value());
  CHECK_FALSE(demonstrate(hammer, miss, 47).reached);
}

TEST_CASE("each method on a hand-picked hammer grasp", "[grasp][transfer]") {
  const GraspObject hammer = objects::hammer();
  const auto hyps = box_hypotheses(hammer);
  // A power grasp that wraps the hammer (its largest winding above 0.5 turns about the centre of
  // mass, which the steel head pulls to 0.117 m along the handle).
  const HumanGrasp g = demonstrate(hammer, hyps[47], 47);
  REQUIRE(g.stable());
  CHECK(g.descriptor.values[0] >= g.descriptor.values[1]);
  CHECK(g.descriptor.values[0] > 0.5);  // the hand wraps the handle
  const TransferOptions options;
  const SdhTransfer topo = transfer_topological(hammer, g, options);
  CHECK(topo.planned);
  CHECK(topo.stable());
  CHECK(topo.sweeps > 0);
  REQUIRE(topo.winding_plan.size() == static_cast<std::size_t>(options.aico.steps + 1));
  // The plan ends nearer the human's windings than it started.
  const Vec2 y = g.descriptor.values;
  CHECK((topo.winding_plan.back() - y).norm() < (topo.winding_plan.front() - y).norm());
  const SdhTransfer transplant = transfer_transplant(hammer, g, options);
  CHECK(transplant.planned);
  CHECK(transplant.stable());
  // The fingertip mapping scales the human tips by the ratio of the digits' lengths: the SDH's
  // thumb, finger 1 and finger 2 (0.1715 m each) against the human thumb, index and ring.
  CHECK((fingertip_scale<models::schunk_sdh, models::human_hand>()) == Approx(2.175).epsilon(2e-3));
  const SdhTransfer fingertip = transfer_fingertip(hammer, g, options);
  CHECK(fingertip.planned);
  // Every test up to the first failure is measured; the suite stops there.
  bool stopped = false;
  for (const StabilityRecord& t : fingertip.stability.tests) {
    INFO(t.name << ": " << t.reason);
    if (stopped) {
      CHECK(t.steps == 0);
      continue;
    }
    CHECK(t.steps > 0);
    CHECK(std::isfinite(t.translation));
    CHECK(std::isfinite(t.force_median));
    stopped = !t.passed;
  }
}

TEST_CASE("the line task keeps the SDH on the part the human held", "[grasp][transfer]") {
  // A grasp of the handle away from the centre of mass (near the head): small human windings,
  // which the planner could also reach by backing the hand away or sliding it off the handle.
  const GraspObject hammer = objects::hammer();
  const HumanGrasp g = demonstrate(hammer, box_hypotheses(hammer)[22], 22);
  REQUIRE(g.stable());
  CHECK(g.descriptor.values[0] < 0.35);
  const Eigen::Isometry3d human = detail::sdh_grasp_target(g);
  const auto off_line = [&](const SdhTransfer& r) {
    const Vec3 off = r.hand_pose * Vec3(0, 0, 0.15) - human.translation();  // SDH grasp_centre
    return (off - off.dot(human.linear().col(2)) * human.linear().col(2)).norm();
  };
  TransferOptions options;
  const SdhTransfer on_line = transfer_topological(hammer, g, options);
  options.line_precision_mid = options.line_precision_end = 0.0;
  const SdhTransfer free = transfer_topological(hammer, g, options);
  INFO("grasp centre off the human's approach line: "
       << off_line(on_line) << " m with the line task, " << off_line(free) << " m without");
  CHECK(off_line(on_line) < 0.02);
  CHECK(off_line(on_line) < 0.5 * off_line(free));
  CHECK(on_line.stable());
}

TEST_CASE("the windings can be taken around the point nearest the human's grasp", "[grasp]") {
  const GraspObject hammer = objects::hammer();
  const HumanGrasp g = demonstrate(hammer, box_hypotheses(hammer)[22], 22);  // on the handle
  REQUIRE(g.stable());
  const Vec3 com = hammer.centre_of_mass();
  CHECK(winding_reference_point(hammer, g, WindingReference::centre_of_mass) == com);
  // The descriptor recomputed from the hand's own frame is the demonstration's.
  CHECK((human_descriptor(g, com).values - g.descriptor.values).norm() < 1e-9);
  const Vec3 p = winding_reference_point(hammer, g, WindingReference::nearest_point);
  const Vec3 c = detail::sdh_grasp_target(g).translation();  // the human's grasp centre
  double surface = std::numeric_limits<double>::infinity();
  const Composite shape = hammer.composite();
  for (const Primitive& part : shape.parts()) surface = std::min(surface, signed_distance(part, p));
  // On the surface (or the grasp centre itself, inside the object), nearer than the COM.
  CHECK((std::abs(surface) < 1e-9 || p == c));
  CHECK((p - c).norm() < (com - c).norm());
  // Around it the human winds more than around the distant centre of mass.
  const Vec2 y = human_descriptor(g, p).values;
  CHECK(y[0] > g.descriptor.values[0]);
  TransferOptions options;
  options.winding_reference = WindingReference::nearest_point;
  const SdhTransfer r = transfer_topological(hammer, g, options);
  CHECK(r.planned);
  REQUIRE(!r.winding_targets.empty());
  CHECK((r.winding_targets.back() - y).norm() < 1e-12);
  CHECK(winding_reference("nearest_point") == WindingReference::nearest_point);
  CHECK(winding_reference("centre_of_mass") == WindingReference::centre_of_mass);
  CHECK_THROWS_WITH(winding_reference("palm"), Catch::StartsWith("winding_reference"));
}

TEST_CASE("bad experiment input is rejected by name", "[grasp][bad-input]") {
  CHECK_THROWS_WITH(transfer_method("teleport"), Catch::Contains("method"));
  CHECK(transfer_method("fingertip") == TransferMethod::fingertip);
  ExperimentOptions c = small_options(0);
  CHECK_THROWS_WITH(run_experiment(c), Catch::Contains("jobs"));
  c = small_options(1);
  c.shard_index = 3;
  c.shard_count = 3;
  CHECK_THROWS_WITH(run_experiment(c), Catch::Contains("shard"));
  c = small_options(1);
  c.objects.clear();
  CHECK_THROWS_WITH(run_experiment(c), Catch::Contains("objects"));
  c = small_options(1);
  c.transfer.sim.stability.direction_steps = 0;  // before any work, named from the experiment
  CHECK_THROWS_WITH(run_experiment(c), Catch::StartsWith("transfer.sim.stability.direction_steps"));
  c = small_options(1);
  c.objects[0].mass = -1.0;
  CHECK_THROWS_WITH(run_experiment(c), Catch::Contains("hammer.mass"));
  c = small_options(1);
  c.transfer.sim.friction = -0.5;
  CHECK_THROWS_WITH(run_experiment(c), Catch::Contains("transfer.sim.friction"));
}

TEST_CASE("transfer parameters are set and recorded by name", "[grasp][bad-input]") {
  TransferOptions o;
  set_transfer_parameter(o, "final_approach", 0.1);
  CHECK(o.final_approach == 0.1);
  set_transfer_parameter(o, "line_precision_end", 0.0);
  CHECK(o.line_precision_end == 0.0);
  CHECK_THROWS_WITH(set_transfer_parameter(o, "reach", 1.0),
                    Catch::StartsWith("name") && Catch::Contains("final_approach"));
  CHECK_THROWS_WITH(set_transfer_parameter(o, "backoff", -0.1), Catch::StartsWith("backoff"));
  CHECK_THROWS_WITH(set_transfer_parameter(o, "backoff", std::nan("")),
                    Catch::StartsWith("backoff"));
  CHECK(o.backoff == TransferOptions{}.backoff);  // unchanged by the rejected calls
  // results.json records every parameter under config.transfer.
  ExperimentOptions c = small_options(1);
  c.transfer = o;
  const Json doc = results_json(c, std::vector<ObjectResult>{});
  const Json& t = doc.at("config").at("transfer");
  for (const TransferParameter& p : transfer_parameters)
    CHECK(t.at(std::string(p.name)).as_number() == p.get(o));
  CHECK(t.at("final_approach").as_number() == 0.1);
  CHECK(t.at("winding_reference").as_string() == "centre_of_mass");
}

TEST_CASE("shards split the hypotheses without overlap", "[grasp][experiment]") {
  ExperimentOptions c = small_options(1);
  c.objects = {objects::can()};
  c.methods = {TransferMethod::transplant};
  int total = 0;
  for (int k = 0; k < 3; ++k) {
    c.shard_index = k;
    c.shard_count = 3;
    const auto r = run_experiment(c);
    for (const HumanGrasp& g : r[0].human) CHECK(g.id % 3 == k);
    total += r[0].hypotheses;
  }
  CHECK(total == 4);
}

TEST_CASE("a run with the power grip (--hypotheses power) records each grip it made",
          "[grasp][experiment]") {
  ExperimentOptions c = small_options(1);
  c.objects = {objects::bottle()};
  c.methods = {TransferMethod::transplant};
  c.hypotheses = HypothesisRule::power;
  c.max_hypotheses = 0;
  c.shard_index = 0;
  c.shard_count = 80;  // ids 0, 80, 160, 240: four faces' first grips
  const std::vector<ObjectResult> r = run_experiment(c);
  const std::vector<GraspHypothesis> expected = power_grip_hypotheses(objects::bottle(), c.seed);
  CHECK(r[0].hypotheses == 4);
  const Json doc = results_json(c, r);
  CHECK(doc.at("config").at("hypotheses").as_string() == "power");
  int humans = 0;
  for (const Json& g : doc.at("grasps").as_array()) {
    if (g.at("method").as_string() != "human") continue;
    ++humans;
    const auto id = static_cast<std::size_t>(g.at("id").as_number());
    REQUIRE(id < expected.size());
    const Json& h = g.at("hypothesis");
    CHECK(h.at("box").as_number() == expected[id].box);
    CHECK(h.at("face").as_number() == expected[id].face);
    CHECK(h.at("roll").as_number() == expected[id].roll);
    CHECK(h.at("jitter_seed").is_null() == (expected[id].jitter_seed == 0));
  }
  CHECK(humans == 4);
}

TEST_CASE("the shuffled-windings control's other demonstration is chosen by a fixed order",
          "[grasp][experiment][controls]") {
  // Halfway round the object's hypotheses, then on, never itself.
  CHECK(shuffle_partner_order(0, 4) == std::vector<int>{2, 3, 1});
  CHECK(shuffle_partner_order(3, 4) == std::vector<int>{1, 2, 0});
  CHECK(shuffle_partner_order(1, 5) == std::vector<int>{3, 4, 0, 2});
  CHECK(shuffle_partner_order(0, 2) == std::vector<int>{1});
  CHECK(shuffle_partner_order(0, 1).empty());
}

TEST_CASE("in a run, the controls: no plan, and the windings of the first partner that reached",
          "[grasp][experiment][controls][end_to_end]") {
  // Each stable demonstration's shuffled transfer aims at the first partner in that order whose
  // human grasp reached the object; its windings differ from the demonstration's own.
  ExperimentOptions c = stable_options(2);
  c.objects = {objects::hammer()};
  c.methods = {TransferMethod::topological, TransferMethod::shuffled_windings,
               TransferMethod::no_plan};
  const std::vector<ObjectResult> r = run_experiment(c);
  REQUIRE(r[0].stable_human() > 0);
  const std::vector<GraspHypothesis> hyps = box_hypotheses(objects::hammer());
  for (std::size_t k = 0; k < r[0].transferred_ids.size(); ++k) {
    const int id = r[0].transferred_ids[k];
    const SdhTransfer& own = r[0].transfers[0][k];
    const SdhTransfer& shuffled = r[0].transfers[1][k];
    const SdhTransfer& none = r[0].transfers[2][k];
    INFO("demonstration " << id << ": " << shuffled.reason);
    CHECK(shuffled.method == TransferMethod::shuffled_windings);
    CHECK(none.method == TransferMethod::no_plan);
    CHECK(none.sweeps == 0);
    std::optional<HumanGrasp> partner;
    for (const int j : shuffle_partner_order(id, static_cast<int>(hyps.size()))) {
      HumanGrasp p = demonstrate(objects::hammer(), hyps[static_cast<std::size_t>(j)], j);
      if (p.reached) {
        partner = std::move(p);
        break;
      }
    }
    REQUIRE(partner.has_value());
    REQUIRE(shuffled.source_winding.has_value());
    REQUIRE(own.source_winding.has_value());
    CHECK(shuffled.source_winding->isApprox(partner->descriptor.values));
    CHECK_FALSE(shuffled.source_winding->isApprox(*own.source_winding));
  }
}

TEST_CASE("the experiment warns of a recording the hand fits badly or cannot be placed at",
          "[grasp][keypoints][experiment]") {
  // A hand 1.5 times the model's (every keypoint scaled about the wrist: a file in the wrong
  // units would be off by far more) at the bottle, and a hand inside a 1 m crate, which backing
  // off by the stand-off does not bring out.
  HandGrasp<models::human_hand> pose;
  pose.root.translation() = Vec3(-0.12, 0.0, 0.05);
  KeypointGrasp large = human_keypoints(pose, "bottle");
  for (Vec3& k : large.keypoints) k = large.keypoints[0] + 1.5 * (k - large.keypoints[0]);
  HandGrasp<models::human_hand> centred;
  const KeypointGrasp inside = human_keypoints(centred, "crate");
  ExperimentOptions o;
  o.objects = {objects::bottle(),
               objects::detail::make(
                   "crate", {{box("", at(0, 0, 0), {0.5, 0.5, 0.5}), materials::cardboard, 20.0}})};
  o.methods = {TransferMethod::topological};
  o.demonstrations = {{"large.json", large}, {"inside.json", inside}};
  std::string warnings;
  const std::vector<ObjectResult> r = run_experiment(o, [&](std::string_view line) {
    if (line.starts_with("warning: ")) warnings += std::string(line) + "\n";
  });
  REQUIRE(r.size() == 2);
  REQUIRE(r[0].human.size() == 1);
  REQUIRE(r[0].human[0].fit_error);
  CHECK(r[0].human[0].fit_error->max > k_keypoint_fit_warning);
  REQUIRE(r[1].human.size() == 1);
  CHECK_FALSE(r[1].human[0].reached);
  CHECK(r[1].human[0].fit_error->max < 1e-3);  // a good fit, but no place for the hand
  CHECK_THAT(warnings,
             Catch::Contains("warning: [bottle] recording large.json (hypothesis 0): the human "
                             "hand fits its keypoints only within") &&
                 Catch::Contains("warning: [crate] recording inside.json (hypothesis 0): the "
                                 "human hand cannot be placed at the object"));
  CHECK_THAT(warnings, !Catch::Contains("inside.json (hypothesis 0): the human hand fits"));
}
