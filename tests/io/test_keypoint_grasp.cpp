// SPDX-License-Identifier: BSD-3-Clause
// Keypoint grasps (io/keypoint_grasp.hpp): the format read in both frames and units, every
// malformed field refused by name, and windings that grow as the keypoint curves wrap a point.
#include <cmath>
#include <string>

#include <catch2/catch.hpp>

#include <topograsp/io/keypoint_grasp.hpp>

using namespace topograsp;

namespace {

// A hand whose curves wrap the z axis by `angle` rad: the thumb on one side, each finger running
// around the axis at radius 0.05 m, at heights 0.00 to 0.03 m; `scale` multiplies every number.
std::string document(double angle, const std::string& extra = "", double scale = 1.0) {
  std::string kps;
  const auto add = [&](double x, double y, double z) {
    kps += (kps.empty() ? "" : ", ") + std::string("[") + std::to_string(scale * x) + ", " +
           std::to_string(scale * y) + ", " + std::to_string(scale * z) + "]";
  };
  add(0.0, -0.08, 0.015);  // wrist
  for (int k = 0; k < 4; ++k) add(0.05 * std::cos(-0.4 * k), 0.05 * std::sin(-0.4 * k), 0.015);
  for (int f = 0; f < 4; ++f)
    for (int k = 0; k < 4; ++k) {
      const double a = 0.4 + angle * k / 3.0;
      add(-0.05 * std::cos(a), -0.05 * std::sin(a), 0.01 * f);
    }
  return "{\"format\": \"topograsp keypoint grasp 1\", \"object\": \"bottle\"" + extra +
         ", \"keypoints\": [" + kps + "]}";
}

}  // namespace

TEST_CASE("a keypoint grasp is read in metres or millimetres, object or world frame",
          "[io][keypoints]") {
  const KeypointGrasp g = parse_keypoint_grasp(document(2.0));
  CHECK(g.object == "bottle");
  CHECK(g.keypoints[0].isApprox(Vec3(0.0, -0.08, 0.015)));
  const KeypointGrasp mm = parse_keypoint_grasp(document(2.0, ", \"units\": \"mm\"", 1000.0));
  for (int i = 0; i < keypoint_count; ++i)
    CHECK((mm.keypoints[static_cast<std::size_t>(i)] - g.keypoints[static_cast<std::size_t>(i)])
              .norm() < 1e-6);
  // In the world frame with the object turned a quarter about z and moved: the keypoints are
  // taken back into the object frame.
  const std::string world =
      document(2.0,
               ", \"frame\": \"world\", \"object_pose\": {\"position\": [0, 0, 0], \"quaternion\": "
               "[0.7071067811865476, 0, 0, 0.7071067811865476]}");
  const KeypointGrasp w = parse_keypoint_grasp(world);
  CHECK((w.keypoints[0] - Vec3(-0.08, 0.0, 0.015)).norm() < 1e-9);
  // A quaternion of huge components is the same rotation (not the identity: its norm overflowed).
  const std::string huge =
      document(2.0,
               ", \"frame\": \"world\", \"object_pose\": {\"position\": [0, 0, 0], \"quaternion\": "
               "[1e200, 0, 0, 1e200]}");
  CHECK((parse_keypoint_grasp(huge).keypoints[0] - w.keypoints[0]).norm() < 1e-9);
  // A signed zero keeps its sign through the writer (found by fuzz_keypoint_grasp).
  KeypointGrasp z = g;
  z.keypoints[2] = Vec3(-0.0, 0.0, -0.0);
  const KeypointGrasp zb = parse_keypoint_grasp(keypoint_grasp_json(z));
  CHECK(std::signbit(zb.keypoints[2].x()));
  CHECK_FALSE(std::signbit(zb.keypoints[2].y()));
}

TEST_CASE("a keypoint grasp written as JSON reads back to the last bit, with its source",
          "[io][keypoints]") {
  KeypointGrasp g = parse_keypoint_grasp(document(1.3));
  g.keypoints[4] = Vec3(0.1, -1.0 / 3.0, 2e-7);
  const std::string text = keypoint_grasp_json(g, "made by hand, for a test");
  CHECK(text.find("\"source\": \"made by hand, for a test\"") != std::string::npos);
  const KeypointGrasp back = parse_keypoint_grasp(text);
  CHECK(back.object == g.object);
  for (int i = 0; i < keypoint_count; ++i)
    CHECK(back.keypoints[static_cast<std::size_t>(i)] == g.keypoints[static_cast<std::size_t>(i)]);
  CHECK(keypoint_grasp_json(g).find("source") == std::string::npos);
}

TEST_CASE("keypoint windings grow as the curves wrap the point", "[io][keypoints]") {
  const Vec3 axis_point(0.0, 0.0, 0.015);
  const Eigen::Vector4d loose = keypoint_windings(parse_keypoint_grasp(document(0.5)), axis_point);
  const Eigen::Vector4d tight = keypoint_windings(parse_keypoint_grasp(document(3.5)), axis_point);
  for (int f = 0; f < 4; ++f) CHECK(tight[f] > loose[f]);
  CHECK(tight.allFinite());
}

TEST_CASE("a malformed keypoint grasp is refused, naming the file and the field",
          "[io][keypoints][bad-input]") {
  const auto refused = [](const std::string& text, const std::string& message) {
    CHECK_THROWS_WITH(parse_keypoint_grasp(text, "g.json"), Catch::StartsWith(message));
  };
  refused("{", "g.json: document: ");
  refused("[1]", "g.json: document: expected a JSON object");
  refused("{\"object\": \"bottle\"}", "g.json: format: missing");
  refused("{\"format\": \"v2\"}", "g.json: format: expected");
  refused(document(1.0, ", \"units\": \"inch\""), "g.json: units: expected \"m\" or \"mm\"");
  refused(document(1.0, ", \"unit\": \"mm\""), "g.json: unit: not a field of the format");
  refused(document(1.0, ", \"source\": 3"), "g.json: source: expected a string");
  refused(
      document(1.0, ", \"object_pose\": {\"position\": [0, 0, 0], \"quaternion\": [1, 0, 0, 0]}"),
      "g.json: object_pose: given, but the frame is not \"world\"");
  refused(document(1.0, ", \"frame\": \"camera\""), "g.json: frame: expected");
  refused(document(1.0, ", \"frame\": \"world\""), "g.json: object_pose: missing");
  refused(document(1.0,
                   ", \"frame\": \"world\", \"object_pose\": {\"position\": [0, 0, 0], "
                   "\"quaternion\": [0, 0, 0, 0]}"),
          "g.json: object_pose.quaternion: has zero length");
  refused(
      "{\"format\": \"topograsp keypoint grasp 1\", \"object\": \"bottle\", \"keypoints\": "
      "[[0, 0, 0]]}",
      "g.json: keypoints: expected 21 keypoints");
  std::string bad = document(1.0);
  bad.replace(bad.find("[0.000000, -0.080000"), 1, "[\"x\", ");
  refused(bad, "g.json: keypoints[0]: expected three");
  // A world pose that moves a keypoint out of the range of double (found by fuzz_keypoint_grasp).
  std::string far =
      document(1.0,
               ", \"frame\": \"world\", \"object_pose\": {\"position\": [-1e308, 0, 0], "
               "\"quaternion\": [1, 0, 0, 0]}");
  far.replace(far.find("[0.000000, -0.080000"), 1, "[1e308, ");
  far.replace(far.find("1e308, 0.000000"), 15, "1e308");
  refused(far, "g.json: keypoints[0]: not finite in the object frame");
  CHECK_THROWS_WITH(read_keypoint_grasp("/nonexistent/g.json"),
                    "/nonexistent/g.json: file: no such file (a regular file is expected)");
}
