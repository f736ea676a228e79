// SPDX-License-Identifier: BSD-3-Clause
#include <array>
#include <filesystem>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include <catch2/catch.hpp>

#include <grasp_transfer/journal.hpp>
#include <grasp_transfer/results.hpp>
#include <topograsp/grasp/keypoint_fit.hpp>

using namespace topograsp;

TEST_CASE("scene paths never leave DIR/scenes", "[io][results][bad-input]") {
  CHECK(scene_path("hammer", 3, "topological") == "scenes/hammer_3_topological.xml");
  CHECK(file_name_part("bottle.v2") == "bottle.v2");
  for (const std::string& name :
       {std::string("../../x"), std::string("a/b"), std::string(""), std::string(".."),
        std::string("."), std::string("/etc/passwd"), std::string("a\\b"), std::string("c\nd\x01"),
        std::string("e\0f", 3), std::string(".hidden"), std::string("\xff\xfe")}) {
    INFO(name);
    const std::string part = file_name_part(name);
    CHECK_FALSE(part.empty());
    CHECK(part.front() != '.');
    for (const char c : part) {
      const bool safe = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') ||
                        (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
      CHECK(safe);
    }
    const std::filesystem::path p(scene_path(name, 0, name));
    // One folder ("scenes") and one plain file name in it.
    CHECK(p.parent_path() == "scenes");
    CHECK(p.filename().string().find('/') == std::string::npos);
    CHECK(p.lexically_normal().string().rfind("scenes/", 0) == 0);
  }
  CHECK(file_name_part("../../x") == "_._.._x");
  CHECK(file_name_part("") == "_");
  // A name longer than a file name may be is cut (ENAMETOOLONG came after the whole run).
  CHECK(file_name_part(std::string(1000, 'a')).size() == max_file_name_part);
}

TEST_CASE("a closing that ends touching nothing is named in the grasp's reason and counted",
          "[io][results]") {
  StabilityResult s;
  s.stable = false;
  s.reason = "shake: the object no longer touches the hand";
  ClosingRecord c;
  c.contacts = 0;
  CHECK(grasp_reason(s, c) ==
        "closing ended with no contact; shake: the object no longer touches the hand");
  c.contacts = 3;
  CHECK(grasp_reason(s, c) == "shake: the object no longer touches the hand");
  s.stable = true;
  s.reason.clear();
  c.contacts = 0;
  CHECK(grasp_reason(s, c).empty());
  // The summaries count such closings (records without a closing, not simulated, are not).
  const auto record = [](Json closing) {
    Json r = Json::object();
    r.set("stable", false);
    r.set("tests", Json::array());
    r.set("closing", std::move(closing));
    r.set("second_judge", Json());
    return r;
  };
  Json none = Json::object(), three = Json::object();
  none.set("contacts", 0);
  three.set("contacts", 3);
  const Json a = record(none), b = record(three), d = record(Json());
  CHECK(detail::stability_summary({&a, &b, &d}).at("no_contact").as_number() == 1.0);
}

TEST_CASE("objects whose names clean to the same file name are refused",
          "[io][results][bad-input]") {
  ExperimentOptions o;
  GraspObject a = objects::can(), b = objects::can();
  a.name = "a/b";
  b.name = "a_b";
  o.objects = {a, b};
  CHECK_THROWS_WITH(check_scene_names(o),
                    Catch::StartsWith("objects: \"a/b\" and \"a_b\" would share the scene files"));
  b.name = "a_c";
  o.objects = {a, b};
  CHECK_NOTHROW(check_scene_names(o));
}

TEST_CASE("the config names each recorded demonstration and the hash of its grasp",
          "[io][results][demonstrations]") {
  HandGrasp<models::human_hand> pose;
  pose.root.translation() = Vec3(-0.12, 0.0, 0.05);
  ExperimentOptions o;
  o.objects = {objects::bottle()};
  o.demonstrations = {{"a.json", human_keypoints(pose, "bottle")}};
  const Json first = results_config(o);
  const Json& d = first.at("demonstrations").as_array().at(0);
  CHECK(d.at("file").as_string() == "a.json");
  CHECK(d.at("fnv1a_64").as_string().size() == 16);
  CHECK(d.at("fnv1a_64").as_string().find_first_not_of("0123456789abcdef") == std::string::npos);
  CHECK(results_config(o).at("demonstrations").dump(0) == first.at("demonstrations").dump(0));
  // The same file name with one keypoint moved by a micrometre: another config, so --resume and
  // merge (which compare configs) refuse to mix the two runs.
  o.demonstrations[0].grasp.keypoints[8].x() += 1e-6;
  const Json second = results_config(o);
  CHECK(second.at("demonstrations").as_array().at(0).at("file").as_string() == "a.json");
  CHECK(detail::first_config_difference(first, second, {}) == "demonstrations");
}

TEST_CASE("a journal line that grasp_transfer did not write is refused naming the file and line",
          "[io][results][bad-input]") {
  const std::filesystem::path path =
      std::filesystem::temp_directory_path() / "topograsp-journal-lines.jsonl";
  ExperimentOptions o;
  o.objects = {objects::bottle()};
  o.methods = {TransferMethod::topological};
  const Json config = results_config(o);
  const auto journal_with = [&](const std::string& line) {
    {
      ResultsJournal j(path, config);
    }  // the config line
    std::ofstream(path, std::ios::app | std::ios::binary)
        << "{\"object\": \"bottle\", \"id\": 0, \"records\": [{\"object\": \"bottle\", \"id\": 0, "
           "\"method\": \"human\"}]}\n"
        << line << "\n";
  };
  journal_with("{\"object\": \"bottle\", \"id\": 1, \"records\": []}");
  const std::vector<JournalEntry> good = read_journal(path, config);
  REQUIRE(good.size() == 2);
  CHECK(good[0].records.size() == 1);
  CHECK(good[1].id == 1);
  const std::string at = "--resume: " + path.string() + ":3: ";
  for (const auto& [line, problem] : std::vector<std::pair<std::string, std::string>>{
           {"{\"object\": \"bottle\", \"id\": 1e300, \"records\": []}",
            "\"id\" is not a whole number in [0, 2^31)"},
           {"{\"object\": \"bottle\", \"id\": 2.5, \"records\": []}",
            "\"id\" is not a whole number in [0, 2^31)"},
           {"{\"object\": \"bottle\", \"id\": -1, \"records\": []}",
            "\"id\" is not a whole number in [0, 2^31)"},
           {"{\"object\": \"bottle\", \"id\": 1}", "no \"records\""},
           {"{\"object\": 7, \"id\": 1, \"records\": []}", "\"object\" is not a name"},
           {"[1, 2]", "expected an object"},
           {"{\"object\": \"bottle\", \"id\": 1, \"records\": [{\"object\": \"bottle\", \"id\": 2, "
            "\"method\": \"human\"}]}",
            "a record of another hypothesis"},
           {"{\"object\": \"bottle\", \"id\": 1, \"records\": [{\"object\": \"bottle\", \"id\": "
            "1}]}",
            "a record without its object, id and method"}}) {
    INFO(line);
    journal_with(line);
    CHECK_THROWS_WITH(read_journal(path, config),
                      Catch::StartsWith(at + problem) && Catch::Contains("without --resume"));
  }
  std::filesystem::remove(path);
}

TEST_CASE("results count distinct demonstrations: the same grasp up to symmetry is one",
          "[io][results][clusters]") {
  ExperimentOptions o;
  o.objects = {objects::bottle()};
  o.methods = {TransferMethod::topological, TransferMethod::transplant};
  const Json config = results_config(o);
  // Demonstrations 0 and 1 are one grasp turned 1 rad about the bottle's axis (z); 2 is another;
  // 3 is not stable. Each method holds all of them but the transplant loses 1 and 2.
  const Vec3 c = objects::bottle().centre_of_mass();
  const auto pose = [&](double turn, double height) {
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = Mat3(Eigen::AngleAxisd(turn, Vec3::UnitZ()));
    T.translation() = c + T.linear() * Vec3(-0.05, 0.0, height);
    return T;
  };
  const auto record = [&](int id, const std::string& method, bool stable,
                          const Eigen::Isometry3d& T) {
    Json r = Json::object();
    r.set("object", "bottle");
    r.set("id", id);
    r.set("method", method);
    r.set("stable", stable);
    r.set("tests", Json::array());
    r.set("second_judge", Json());
    if (method == "human") {
      r.set("hand_pose", detail::json_pose(T));
      r.set("joints", detail::json_vector(Vec<20>::Constant(0.4)));
      Json closing = Json::object();  // the object moved id cm while the hand closed
      closing.set("object_shift", 0.01 * id);
      closing.set("object_turn", 0.1 * id);
      closing.set("contacts", 5);
      closing.set("touching_joints", 4);
      r.set("closing", closing);
      r.set("collider_error", 0.0);
    } else {
      r.set("closing", Json());  // a transfer's closing (none here: nothing was simulated)
    }
    return r;
  };
  std::vector<Json> records;
  const std::array<Eigen::Isometry3d, 4> poses{pose(0.0, 0.0), pose(1.0, 0.0), pose(0.0, 0.05),
                                               pose(0.0, 0.0)};
  for (int id = 0; id < 4; ++id) {
    records.push_back(record(id, "human", id < 3, poses[static_cast<std::size_t>(id)]));
    if (id == 3) continue;
    records.push_back(record(id, "topological", true, {}));
    records.push_back(record(id, "transplant", id == 0, {}));
  }
  const Json doc = results_document(config, {ObjectRecords{"bottle", 4, records}});
  std::vector<std::pair<int, Json>> clusters;
  for (const Json& g : doc.at("grasps").as_array())
    if (g.at("method").as_string() == "human")
      clusters.emplace_back(static_cast<int>(g.at("id").as_number()), g.at("cluster"));
  REQUIRE(clusters.size() == 4);
  CHECK(clusters[0].second.as_number() == 0);
  CHECK(clusters[1].second.as_number() == 0);
  CHECK(clusters[2].second.as_number() == 2);
  CHECK(clusters[3].second.is_null());  // not stable: in no cluster
  const Json& bottle = doc.at("objects").as_array().front();
  CHECK(bottle.at("stable_human").as_number() == 3);
  CHECK(bottle.at("distinct_human").as_number() == 2);
  const Json& transplant = bottle.at("methods").at("transplant");
  CHECK(transplant.at("distinct").at("tested").as_number() == 2);
  CHECK(transplant.at("distinct").at("stable").as_number() == 1);  // 0 held, 2 lost
  CHECK(transplant.at("paired_distinct").at("only_against").as_number() == 1);
  // The demonstrations' own summary; without a second judge its counts are null.
  const Json& demos = bottle.at("demonstrations");
  CHECK(demos.at("hypotheses").as_number() == 4);
  CHECK(demos.at("reached").as_number() == 4);
  CHECK(demos.at("touching").as_number() == 4);
  CHECK(demos.at("stable").as_number() == 3);
  CHECK(demos.at("distinct").as_number() == 2);
  CHECK(demos.at("stable_second").is_null());
  CHECK(demos.at("stable_both").is_null());
  CHECK(demos.at("kappa_touching").is_null());
  CHECK(demos.at("median_object_shift").as_number() == Approx(0.015));
  CHECK(demos.at("median_object_turn").as_number() == Approx(0.15));
  {
    // MuJoCo holds demonstrations 0 and 2, drops 1 (a member of 0's cluster) and 3: stable in
    // both 2, in 2 distinct grasps; agreement 3 of 4, kappa (0.75 - 0.5) / (1 - 0.5).
    std::vector<Json> judged = records;
    for (Json& r : judged) {
      if (r.at("method").as_string() != "human") continue;
      const int id = static_cast<int>(r.at("id").as_number());
      Json j = Json::object();
      j.set("engine", "mujoco");
      j.set("stable", id == 0 || id == 2);
      j.set("reason", "");
      j.set("collider_error", 0.0);
      j.set("tests", Json::array());
      r.set("second_judge", j);
    }
    const Json both = results_document(config, {ObjectRecords{"bottle", 5, judged}});
    const Json& d = both.at("objects").as_array().front().at("demonstrations");
    CHECK(d.at("hypotheses").as_number() == 5);
    CHECK(d.at("stable_second").as_number() == 2);
    CHECK(d.at("stable_both").as_number() == 2);
    CHECK(d.at("distinct_both").as_number() == 2);
    CHECK(d.at("agreement_touching").as_number() == Approx(0.75));
    CHECK(d.at("kappa_touching").as_number() == Approx(0.5));
    CHECK(both.at("overall").at("demonstrations").at("distinct_both").as_number() == 2);
  }
  // A stable demonstration without its hand pose is refused.
  records[0] = Json::object();
  records[0].set("object", "bottle");
  records[0].set("id", 0);
  records[0].set("method", "human");
  records[0].set("stable", true);
  CHECK_THROWS(results_document(config, {ObjectRecords{"bottle", 4, records}}));
}
