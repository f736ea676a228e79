// SPDX-License-Identifier: BSD-3-Clause
// The box decomposition (geometry/box_decomposition.hpp): the minimum-volume box of a turned box's
// points, one box for a box, two for an L, and what it does with bad input.
#include <cmath>
#include <limits>
#include <vector>

#include <catch2/catch.hpp>

#include <topograsp/geometry/box_decomposition.hpp>

#include "support/meshes.hpp"

using namespace topograsp;

namespace {

// Points on a grid filling the box [lo, hi] (every `step` m), turned by R about the origin.
std::vector<Vec3> grid(const Vec3& lo, const Vec3& hi, double step,
                       const Mat3& R = Mat3::Identity()) {
  std::vector<Vec3> out;
  for (double x = lo.x(); x <= hi.x() + 1e-12; x += step)
    for (double y = lo.y(); y <= hi.y() + 1e-12; y += step)
      for (double z = lo.z(); z <= hi.z() + 1e-12; z += step) out.push_back(R * Vec3(x, y, z));
  return out;
}

}  // namespace

TEST_CASE("the minimum-volume box of a turned box's points is that box", "[geometry][boxes]") {
  const Mat3 R = (Eigen::AngleAxisd(0.4, Vec3::UnitZ()) * Eigen::AngleAxisd(0.3, Vec3::UnitX()))
                     .toRotationMatrix();
  const std::vector<Vec3> points = grid(Vec3(0, 0, 0), Vec3(0.2, 0.1, 0.05), 0.01, R);
  const OrientedBox b = minimum_volume_box(points);
  CHECK(b.volume() == Approx(0.2 * 0.1 * 0.05).epsilon(0.01));
  CHECK((b.centre - R * Vec3(0.1, 0.05, 0.025)).norm() < 1e-3);
  BoxDecompositionOptions options;
  options.resolution = 0.01;                              // the grid's spacing
  CHECK(box_decomposition(points, options).size() == 1);  // nothing to gain by splitting a box
}

TEST_CASE("an L splits into its two boxes", "[geometry][boxes]") {
  std::vector<Vec3> points = grid(Vec3(0, 0, 0), Vec3(0.3, 0.05, 0.05), 0.01);
  const std::vector<Vec3> leg = grid(Vec3(0, 0.06, 0), Vec3(0.05, 0.3, 0.05), 0.01);
  points.insert(points.end(), leg.begin(), leg.end());
  BoxDecompositionOptions options;
  options.resolution = 0.01;  // the grid's spacing
  const std::vector<OrientedBox> boxes = box_decomposition(points, options);
  REQUIRE(boxes.size() == 2);
  double volume = 0.0;
  for (const OrientedBox& b : boxes) volume += b.volume();
  // The two grown boxes: the bar 0.31 x 0.06 x 0.06 and the leg 0.06 x 0.25 x 0.06.
  CHECK(volume == Approx(0.31 * 0.06 * 0.06 + 0.06 * 0.25 * 0.06).epsilon(0.05));
  CHECK(volume < 0.5 * minimum_volume_box(points).volume());
}

TEST_CASE("the error of boxes against a mesh: none for the box itself, the gaps of a wrong box",
          "[geometry][boxes]") {
  const TriangleMesh m = test::box_mesh(0.2, 0.1, 0.05);
  OrientedBox exact;
  exact.centre = Vec3(0.1, 0.05, 0.025);
  exact.half = Vec3(0.1, 0.05, 0.025);
  const DecompositionError e = decomposition_error(m, std::vector<OrientedBox>{exact}, 0.01);
  CHECK(e.volume_ratio == Approx(1.0));
  CHECK(e.max_distance < 1e-12);
  OrientedBox grown = exact;
  grown.half += Vec3::Constant(0.01);  // 1 cm beyond every face
  const DecompositionError g = decomposition_error(m, std::vector<OrientedBox>{grown}, 0.01);
  CHECK(g.volume_ratio > 1.5);
  CHECK(g.max_distance == Approx(0.01));
  CHECK(g.mean_distance == Approx(0.01));
  CHECK_THROWS_WITH(decomposition_error(m, std::vector<OrientedBox>{}, 0.01),
                    Catch::StartsWith("boxes: "));
}

TEST_CASE("the box decomposition refuses bad input", "[geometry][boxes][bad-input]") {
  CHECK_THROWS_WITH(minimum_volume_box(std::vector<Vec3>{}), Catch::StartsWith("points: "));
  const std::vector<Vec3> nan{Vec3(0, 0, std::numeric_limits<double>::quiet_NaN())};
  CHECK_THROWS_WITH(box_decomposition(nan), Catch::StartsWith("points: "));
  BoxDecompositionOptions bad;
  bad.gain = 1.5;
  CHECK_THROWS_WITH(box_decomposition(std::vector<Vec3>{Vec3::Zero()}, bad),
                    Catch::StartsWith("options: "));
  CHECK_THROWS_WITH(surface_points(TriangleMesh{}, 0.0), Catch::StartsWith("spacing: "));
}
