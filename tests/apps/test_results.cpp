// SPDX-License-Identifier: BSD-3-Clause
#include <filesystem>
#include <string>

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
