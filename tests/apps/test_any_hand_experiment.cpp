// SPDX-License-Identifier: BSD-3-Clause
// The experiment with another hand than the SDH (grasp_transfer --hand): run_experiment<M> on the
// Barrett hand, its results.json against the shipped schema with the Barrett's joints by name, its
// scenes held in MuJoCo, and the options it refuses; a robot hand as the demonstrator
// (grasp_transfer --source): source grasps as JSON, read back from a run and transferred.
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <grasp_transfer/experiment.hpp>
#include <grasp_transfer/journal.hpp>
#include <grasp_transfer/results.hpp>
#include <grasp_transfer/source_json.hpp>
#include <grasp_transfer/source_run.hpp>
#include <topograsp/io/json_schema.hpp>
#include <topograsp/io/ycb_objects.hpp>
#include <topograsp/model/models/barrett_bh8.hpp>
#ifdef TOPOGRASP_HAVE_MUJOCO
#include <topograsp/mujoco/mujoco_scene.hpp>
#endif

using namespace topograsp;

namespace {

constexpr auto& barrett = models::barrett_bh8;

ExperimentOptions barrett_options() {
  ExperimentOptions c;
  c.objects = {objects::bottle()};
  c.methods = {TransferMethod::topological, TransferMethod::autoclose, TransferMethod::transplant};
  c.max_hypotheses = 2;  // the bottle's hypothesis 0 is a stable demonstration
  c.jobs = 2;
  return c;
}

}  // namespace

// Left out where no end-to-end test runs (the sanitizer build, tests/CMakeLists.txt).
#ifndef TOPOGRASP_TESTS_RUN_NO_END_TO_END
TEST_CASE("the experiment on the Barrett hand: records by its joint names, scenes, schema",
          "[grasp][experiment][end_to_end]") {
  ExperimentOptions c = barrett_options();
  SecondJudge<barrett> second;
#ifdef TOPOGRASP_HAVE_MUJOCO
  c.judge = Judge::both;
  c.transfer.sim.second_judge_human = [](const HandScene<models::human_hand>& s,
                                         const StabilityOptions& o) {
    return stability_suite(MujocoScene(s), o);
  };
  second = [](const HandScene<barrett>& s, const StabilityOptions& o) {
    return stability_suite(MujocoScene(s), o);
  };
#endif
  // The MJCF text of every planned transfer, by (demonstration id, method), as grasp_transfer
  // writes it.
  std::map<std::pair<int, TransferMethod>, std::string> scenes;
  const HypothesisDoneFnOf<barrett> on_done = [&](const GraspObject& object, const HumanGrasp& g,
                                                  const std::vector<HandTransfer<barrett>>& ts) {
    for (const HandTransfer<barrett>& t : ts)
      if (t.planned)
        scenes[{g.id, t.method}] = grasp_mjcf<barrett>(
            object, t.hand_pose, t.q_closed, t.object_pose, t.closing.hold_torque, c.transfer);
  };
  const std::vector<ObjectResultOf<barrett>> results =
      run_experiment<barrett>(c, {}, on_done, second);
  REQUIRE(results.size() == 1);
  REQUIRE(results[0].stable_human() >= 1);
  const Json doc = Json::parse(results_json(c, results).dump(2));
  const Json schema = Json::parse(
      detail::read_text_file(data_directory() + "/schemas/results.schema.json", "schema"));
  CHECK(validate_json(doc, schema).empty());
  CHECK(doc.at("config").at("hand").as_string() == "barrett_bh8");
  // Every placed transfer's configurations hold the Barrett's joints, by its names.
  std::vector<std::string> names;
  for (int i = 0; i < barrett.nq; ++i) names.emplace_back(barrett.joint_name(i));
  int placed = 0;
  for (const Json& g : doc.at("grasps").as_array()) {
    if (g.at("method").as_string() == "human" || g.at("configurations").is_null()) continue;
    ++placed;
    for (const char* which : {"grasp", "closed"}) {
      const Json& joints = g.at("configurations").at(which).at("joints");
      std::vector<std::string> keys;
      for (const std::string& name : names)
        if (joints.contains(name)) keys.push_back(name);
      CHECK(keys == names);
    }
    // The topological plan's joints: the free base's six coordinates, then the Barrett's (no arm).
    if (g.at("method").as_string() == "topological" && !g.at("motion").is_null()) {
      std::vector<std::string> planned;
      for (const Json& j : g.at("motion").at("joints").as_array()) planned.push_back(j.as_string());
      std::vector<std::string> expected{"base_x",  "base_y",  "base_z",
                                        "base_rz", "base_ry", "base_rx"};
      expected.insert(expected.end(), names.begin(), names.end());
      CHECK(planned == expected);
      for (const Json& step : g.at("motion").at("q").as_array())
        CHECK(step.as_array().size() == expected.size());
    }
  }
  CHECK(placed == static_cast<int>(scenes.size()));
  CHECK(placed >= 1);
#ifdef TOPOGRASP_HAVE_MUJOCO
  // A scene both engines hold opens in MuJoCo with the hand holding the object: left alone for a
  // second under gravity, the object stays within 5 mm.
  int held = 0;
  for (const auto& ts : results[0].transfers)
    for (std::size_t k = 0; k < ts.size(); ++k) {
      const HandTransfer<barrett>& t = ts[k];
      if (!(t.stable() && t.second && t.second->stable)) continue;
      MujocoScene scene(scenes.at({results[0].transferred_ids[k], t.method}));
      const Vec3 start = scene.object_pose().translation();
      const int steps = static_cast<int>(1.0 / scene.time_step());
      for (int i = 0; i < steps; ++i) (void)scene.step();
      INFO(to_string(t.method));
      CHECK((scene.object_pose().translation() - start).norm() < 0.005);
      ++held;
    }
  CHECK(held >= 1);
#endif
}
#endif

TEST_CASE("the experiment on another hand refuses what only the SDH on the arm runs",
          "[grasp][experiment][bad-input]") {
  ExperimentOptions c = barrett_options();
  CHECK_NOTHROW(validate_experiment_options<barrett>(c));
  c.methods = {TransferMethod::topological, TransferMethod::closed_windings};
  CHECK_THROWS_WITH(validate_experiment_options<barrett>(c),
                    "methods: \"closed_windings\" runs with the SDH on the arm only; the "
                    "barrett_bh8 is placed on a free base (docs/transfer.md, \"Any hand\")");
  c.methods = {TransferMethod::shuffled_windings};
  CHECK_THROWS_WITH(validate_experiment_options<barrett>(c),
                    Catch::StartsWith("methods: \"shuffled_windings\" runs with the SDH"));
  CHECK_NOTHROW(validate_experiment_options(c));  // the SDH runs it
  c = barrett_options();
  c.arm_setting = true;
  CHECK_THROWS_WITH(validate_experiment_options<barrett>(c),
                    "arm_setting: the arm carries the SDH only; the barrett_bh8 is placed on a "
                    "free base (--setting hand)");
  c = barrett_options();
  c.judge = Judge::both;
  c.transfer.sim.second_judge_human = [](const HandScene<models::human_hand>&,
                                         const StabilityOptions&) { return StabilityResult{}; };
  // The SDH's second judge is not the Barrett's.
  c.transfer.sim.second_judge_sdh = [](const HandScene<models::schunk_sdh>&,
                                       const StabilityOptions&) { return StabilityResult{}; };
  CHECK_THROWS_WITH(validate_experiment_options<barrett>(c),
                    "judge: --judge both needs a second judge (transfer.sim.second_judge_human "
                    "and the barrett_bh8's)");
  const SecondJudge<barrett> judge = [](const HandScene<barrett>&, const StabilityOptions&) {
    return StabilityResult{};
  };
  CHECK_NOTHROW(validate_experiment_options<barrett>(c, judge));
}

namespace {

// Whether two source grasps hold the same numbers, to the last bit.
bool same_source(const SourceGrasp& a, const SourceGrasp& b) {
  if (a.hand != b.hand || a.thumb != b.thumb || a.unusable != b.unusable || a.curves != b.curves ||
      a.digits.size() != b.digits.size() || a.palm.size() != b.palm.size())
    return false;
  for (const auto& [x, y] : {std::pair{&a.root, &b.root}, std::pair{&a.grasp_frame, &b.grasp_frame},
                             std::pair{&a.palm_frame, &b.palm_frame}})
    if (x->matrix() != y->matrix()) return false;
  for (std::size_t f = 0; f < a.digits.size(); ++f)
    if (a.digits[f].tip != b.digits[f].tip || a.digits[f].length != b.digits[f].length)
      return false;
  for (std::size_t k = 0; k < a.palm.size(); ++k)
    if (a.palm[k].type != b.palm[k].type || a.palm[k].R != b.palm[k].R ||
        a.palm[k].p != b.palm[k].p || a.palm[k].size != b.palm[k].size)
      return false;
  return true;
}

// A grasp of the Barrett hand away from the identity: turned, moved, its joints half closed.
SourceGrasp barrett_source() {
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = Eigen::AngleAxisd(0.7, Vec3(0.3, -0.5, 0.8).normalized()).toRotationMatrix();
  T.translation() = Vec3(0.11, -0.023, 0.3);
  return describe_source(HandGrasp<barrett>{T, Vec<barrett.nq>::Constant(0.4)});
}

}  // namespace

TEST_CASE("a source grasp as JSON reads back to the last bit; a spoiled one is refused by field",
          "[grasp][experiment][source][bad-input]") {
  const SourceGrasp s = barrett_source();
  REQUIRE(unusable_source(s).empty());
  const Json j = source_grasp_json(s);
  CHECK(same_source(source_grasp_of(Json::parse(j.dump(2)), "g"), s));
  const Json schema = Json::parse(
      detail::read_text_file(data_directory() + "/schemas/results.schema.json", "schema"));
  Json def = schema.at("$defs").at("source_grasp");
  def.set("$defs", schema.at("$defs"));
  CHECK(validate_json(j, def).empty());
  // An unusable source is not written.
  SourceGrasp bad = s;
  bad.unusable = "the source hand pose is not finite";
  CHECK(source_grasp_json(bad).is_null());
  // Each spoiled field named by its path.
  const auto spoiled = [&](const std::string& text) {
    return source_grasp_of(Json::parse(text), "grasps[3].source_grasp");
  };
  std::string text = j.dump(0);
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string t = text;
    const std::size_t at = t.find(from);
    REQUIRE(at != std::string::npos);
    return t.replace(at, from.size(), to);
  };
  CHECK_THROWS_WITH(spoiled(replaced("\"thumb\":", "\"thumb\":7,\"x\":")),
                    "grasps[3].source_grasp.thumb: expected the index of one of the digits");
  CHECK_THROWS_WITH(spoiled(replaced("\"palm\":", "\"palm_shapes\":")),
                    "grasps[3].source_grasp: missing \"palm\"");
  CHECK_THROWS_WITH(spoiled(replaced("\"type\":\"", "\"type\":\"cone")),
                    Catch::StartsWith("grasps[3].source_grasp.palm[0].type: expected sphere"));
  CHECK_THROWS_WITH(spoiled(replaced("\"curves\":[[[", "\"curves\":[[[\"a\",")),
                    "grasps[3].source_grasp.curves[0][0]: expected an array of 3 numbers");
  CHECK_THROWS_WITH(spoiled(replaced("\"root\":{\"position\":[", "\"root\":{\"position\":[1,")),
                    "grasps[3].source_grasp.root.position: expected an array of 3 numbers");
  CHECK_THROWS_WITH(spoiled(replaced("\"rotation\":[", "\"rotation\":[2,")),
                    "grasps[3].source_grasp.root.rotation: expected an array of 9 numbers");
  // Read whole, but not a hand: a frame that is not a rigid transform (unusable_source).
  Json stretched = j;
  Json root = j.at("root");
  Json::Array r = root.at("rotation").as_array();
  r[0] = Json(2.0 * r[0].as_number());
  root.set("rotation", Json(std::move(r)));
  stretched.set("root", root);
  CHECK_THROWS_WITH(source_grasp_of(stretched, "grasps[3].source_grasp"),
                    "grasps[3].source_grasp: a frame of the source hand is not a rigid transform");
}

#ifndef TOPOGRASP_TESTS_RUN_NO_END_TO_END
TEST_CASE("a robot hand as the demonstrator: its stable transfers, read from its run, transferred",
          "[grasp][experiment][source][end_to_end]") {
  // The Barrett's run (built-in judge) written as grasp_transfer writes it: results.json and the
  // scenes of its planned transfers.
  const ExperimentOptions s = barrett_options();
  const std::vector<ObjectResultOf<barrett>> ran = run_experiment<barrett>(s);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("topograsp_test_source_" + detail::temporary_file_token());
  std::filesystem::create_directories(dir / "scenes");
  const GraspObject& bottle = s.objects[0];
  std::vector<const HandTransfer<barrett>*> sources;  // the stable topological transfers
  for (std::size_t m = 0; m < s.methods.size(); ++m)
    for (std::size_t k = 0; k < ran[0].transfers[m].size(); ++k) {
      const HandTransfer<barrett>& t = ran[0].transfers[m][k];
      if (!t.planned) continue;
      detail::write_text_file(
          dir / scene_path(bottle.name, ran[0].transferred_ids[k], to_string(t.method)),
          grasp_mjcf<barrett>(bottle, t.hand_pose, t.q_closed, t.object_pose, t.closing.hold_torque,
                              s.transfer));
      if (t.method == TransferMethod::topological && t.stable()) sources.push_back(&t);
    }
  REQUIRE(!sources.empty());
  const Json doc = results_json(s, ran);
  detail::write_text_file(dir / "results.json", doc.dump(2) + "\n");

  // The Barrett's grasps transferred to the Barrett by two methods.
  ExperimentOptions t = barrett_options();
  t.methods = {TransferMethod::topological, TransferMethod::transplant};
  read_source_run(dir, {}, t);
  REQUIRE(t.sources.size() == sources.size());
  CHECK(t.source_hand == "barrett_bh8");
  const std::string file = std::filesystem::weakly_canonical(dir / "results.json").string();
  CHECK(t.source_results == file);
  CHECK_NOTHROW(check_source_config(t, results_config(t, barrett.name.view())));
  for (std::size_t k = 0; k < sources.size(); ++k)
    CHECK(same_source(t.sources[k].grasp, describe_source(source_grasp(*sources[k]))));
  const std::vector<ObjectResultOf<barrett>> out = run_experiment<barrett>(t);
  REQUIRE(out[0].stable_human() == static_cast<int>(sources.size()));
  // Each transfer is the one transfer_hand makes of the source grasp with the same seed.
  for (std::size_t m = 0; m < t.methods.size(); ++m)
    for (std::size_t k = 0; k < sources.size(); ++k) {
      TransferOptions o = t.transfer;
      o.sim.stability.seed = grasp_seed(t.seed, bottle.name, out[0].transferred_ids[k]);
      const HandTransfer<barrett> direct = transfer_hand<barrett>(
          t.methods[m], bottle, describe_source(source_grasp(*sources[k])), o);
      const HandTransfer<barrett>& got = out[0].transfers[m][k];
      CHECK(got.planned == direct.planned);
      CHECK(got.stable() == direct.stable());
      CHECK(got.hand_pose.matrix() == direct.hand_pose.matrix());
      CHECK(got.q_closed == direct.q_closed);
    }
  // Its results: the demonstrations are the source's records, by the schema.
  const Json result = Json::parse(results_json(t, out).dump(2));
  const Json schema = Json::parse(
      detail::read_text_file(data_directory() + "/schemas/results.schema.json", "schema"));
  CHECK(validate_json(result, schema).empty());
  CHECK(result.at("config").at("source").at("hand").as_string() == "barrett_bh8");
  int demonstrations = 0;
  for (const Json& g : result.at("grasps").as_array()) {
    if (g.at("method").as_string() != "source") continue;
    ++demonstrations;
    CHECK(g.at("hand").as_string() == "barrett_bh8");
    CHECK(g.at("stable").as_bool());
    CHECK(g.at("joints").as_array().size() == static_cast<std::size_t>(barrett.nq));
    CHECK(g.at("scene").as_string() ==
          scene_path(bottle.name, static_cast<int>(g.at("id").as_number()), "source"));
  }
  CHECK(demonstrations == static_cast<int>(sources.size()));
  CHECK(result.at("objects").as_array()[0].at("stable_human").as_number() == demonstrations);

  // What it refuses, naming --source, the file and the field.
  const auto read_doc = [&](const Json& d) {
    detail::write_text_file(dir / "results.json", d.dump(0));
    ExperimentOptions o = barrett_options();
    read_source_run(dir, {}, o);
  };
  CHECK_THROWS_WITH(
      read_source_run(dir / "none", {}, t),
      Catch::StartsWith("--source: \"" + (dir / "none").string() + "\" does not exist"));
  CHECK_THROWS_WITH(
      read_source_run(dir, {"hammer"}, t),
      "--source: " + file + ": config.objects: the run has no object \"hammer\" (--objects)");
  Json old = doc;
  old.set("schema_version", 4);
  CHECK_THROWS_WITH(read_doc(old),
                    Catch::StartsWith("--source: " + file + ": schema_version: expected 5"));
  std::size_t first = 0;  // the first source's record
  const Json::Array& records = doc.at("grasps").as_array();
  while (!(records[first].at("method").as_string() == "topological" &&
           records[first].at("stable").as_bool()))
    ++first;
  const std::string at = "grasps[" + std::to_string(first) + "]";
  Json::Array spoiled = records;
  spoiled[first].set("source_grasp", Json());
  Json without = doc;
  without.set("grasps", Json(spoiled));
  CHECK_THROWS_WITH(read_doc(without),
                    "--source: " + file + ": " + at + ".source_grasp: expected an object");
  // Whatever the schema refuses (a record copied into this run's results must be sound).
  const auto with_record = [&](const Json& record) {
    Json::Array r = records;
    r[first] = record;
    Json d = doc;
    d.set("grasps", Json(std::move(r)));
    return d;
  };
  const std::string pointer = "/grasps/" + std::to_string(first);
  // Whether reading d is refused by the schema at the field `field` of the first source's record.
  const auto refused_at = [&](const Json& d, const std::string& field) {
    std::string message;
    try {
      read_doc(d);
    } catch (const invalid_argument& e) {
      message = e.what();
    }
    return message.starts_with("--source: " + file + ": schema: " + pointer) &&
           message.find(pointer + field) != std::string::npos;
  };
  Json record = records[first];
  record.set("configurations", Json::object());
  CHECK(refused_at(with_record(record), "/configurations"));
  for (const double id : {2.5, -1.0, 4294967296.0}) {
    record = records[first];
    record.set("id", id);
    CHECK(refused_at(with_record(record), "/id: "));
  }
  record = records[first];
  record.set("object", 3);
  CHECK(refused_at(with_record(record), "/object: expected string"));
  // What the schema cannot say: the scene is the one grasp_transfer writes, beside the file.
  const std::string id_text = std::to_string(static_cast<int>(records[first].at("id").as_number()));
  record = records[first];
  record.set("scene", "../../etc/passwd");
  CHECK_THROWS_WITH(read_doc(with_record(record)), "--source: " + file + ": " + at +
                                                       ".scene: expected \"scenes/bottle_" +
                                                       id_text + "_topological.xml\"");
  record = records[first];
  Json grasp = record.at("source_grasp");
  grasp.set("hand", "human_hand");
  record.set("source_grasp", grasp);
  CHECK_THROWS_WITH(
      read_doc(with_record(record)),
      "--source: " + file + ": " + at +
          ".source_grasp.hand: \"human_hand\", but the run's hand is \"barrett_bh8\"");
  Json twice = doc;
  Json::Array doubled = records;
  doubled.push_back(records[first]);
  twice.set("grasps", Json(doubled));
  CHECK_THROWS_WITH(read_doc(twice), "--source: " + file + ": grasps[" +
                                         std::to_string(records.size()) + "]: bottle hypothesis " +
                                         id_text + " by topological is given twice");
  Json shard = doc;
  Json config = doc.at("config");
  config.set("shard", "2/2");
  shard.set("config", config);
  CHECK_THROWS_WITH(read_doc(shard), "--source: " + file +
                                         ": config.shard: a shard of a run (2/2): merge its shards "
                                         "first (grasp_transfer merge)");
  Json unstable = doc;
  spoiled = records;
  for (Json& r : spoiled) r.set("stable", false);
  unstable.set("grasps", Json(spoiled));
  CHECK_THROWS_WITH(
      read_doc(unstable),
      "--source: " + file + ": grasps: no stable topological transfer to take as a demonstration");
  // A source judged otherwise than this run.
  ExperimentOptions other = t;
  other.seed = 2;
  CHECK_THROWS_WITH(check_source_config(other, results_config(other, barrett.name.view())),
                    "--source: " + file +
                        ": its config's \"seed\" is \"1\", this run's \"2\" (a demonstration is "
                        "judged as its transfers are: run both alike)");
  std::filesystem::remove_all(dir);
}
#endif

TEST_CASE(
    "the experiment refuses sources with what transfers a human demonstration only, and bad "
    "sources",
    "[grasp][experiment][source][bad-input]") {
  ExperimentOptions c = barrett_options();
  c.sources.push_back({"bottle", 4, barrett_source(), Json(), ""});
  CHECK_NOTHROW(validate_experiment_options<barrett>(c));
  CHECK_NOTHROW(validate_experiment_options(c));  // the SDH takes it on a free base
  c.methods = {TransferMethod::topological, TransferMethod::closed_windings};
  CHECK_THROWS_WITH(validate_experiment_options(c),
                    "methods: \"closed_windings\" transfers a human demonstration only (on the "
                    "SDH on the arm); a robot hand's grasp is transferred on a free base");
  c = barrett_options();
  c.sources.push_back({"bottle", 4, barrett_source(), Json(), ""});
  c.arm_setting = true;
  CHECK_THROWS_WITH(validate_experiment_options(c),
                    "sources: a robot hand's grasps are transferred on a free base, not in the "
                    "arm setting");
  c.arm_setting = false;
  c.demonstrations.push_back({"a.json", KeypointGrasp{}});
  c.demonstrations.back().grasp.object = "bottle";
  CHECK_THROWS_WITH(validate_experiment_options(c), "sources: not with recorded demonstrations");
  c.demonstrations.clear();
  c.sources.push_back(c.sources.back());
  CHECK_THROWS_WITH(validate_experiment_options(c),
                    "sources[1]: bottle hypothesis 4 is given twice");
  c.sources.back().object = "hammer";
  CHECK_THROWS_WITH(validate_experiment_options(c),
                    "sources[1].object: \"hammer\" is not an object of the run");
  c.sources.back() = {"bottle", -3, barrett_source(), Json(), ""};
  CHECK_THROWS_WITH(validate_experiment_options(c),
                    "sources[1].id: expected >= 0 (a hypothesis id), got -3");
}
