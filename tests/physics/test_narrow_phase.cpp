// SPDX-License-Identifier: BSD-3-Clause
// The narrow phase against closed-form distances, normals and point counts.
#include "physics_test_support.hpp"

#include <cmath>

#include <catch2/catch.hpp>

using namespace topograsp;
using V3 = Eigen::Vector3d;

namespace {

struct Placed {
  ShapeSpec spec;
  Polytope<double> poly;
  ShapeView<double> view;
};

Placed place(const ShapeSpec& s, const Eigen::Isometry3d& T) {
  Placed p;
  p.spec = s;
  p.view.type = s.type;
  p.view.size = V3(s.size[0], s.size[1], s.size[2]);
  p.view.R = T.linear();
  p.view.p = T.translation();
  if (s.type == ShapeType::box) p.poly = box_polytope<double>(p.view.size);
  if (s.type == ShapeType::cylinder) p.poly = cylinder_polytope<double>(s.size[0], s.size[1]);
  return p;
}

ContactSet<double> contacts(Placed& a, Placed& b, double margin = 0.005) {
  a.view.polytope = &a.poly;
  b.view.polytope = &b.poly;
  ContactSet<double> cs;
  collide(a.view, b.view, margin, cs);
  return cs;
}

Eigen::Isometry3d at3(double x, double y, double z) {
  return Eigen::Isometry3d(Eigen::Translation3d(x, y, z));
}

}  // namespace

TEST_CASE("a sphere near a box corner gets the diagonal normal and distance", "[physics][narrow]") {
  Placed b = place(box("", Pose{}, {0.1, 0.1, 0.1}), Eigen::Isometry3d::Identity());
  const double d = 0.002;  // gap along the diagonal
  const double k = 0.1 + (0.05 + d) / std::sqrt(3.0);
  Placed s = place(sphere("", {0, 0, 0}, 0.05), at3(k, k, k));
  const auto cs = contacts(s, b);
  REQUIRE(cs.count == 1);
  CHECK(cs.points[0].separation == Approx(d).epsilon(1e-6));
  CHECK(cs.points[0].normal.isApprox(-V3(1, 1, 1).normalized(), 1e-6));
  // Further than the margin: nothing.
  Placed far = place(sphere("", {0, 0, 0}, 0.05), at3(k + 0.01, k + 0.01, k + 0.01));
  CHECK(contacts(far, b).count == 0);
}

TEST_CASE("a capsule lying on a box face gets two points", "[physics][narrow]") {
  Placed b = place(box("", Pose{}, {0.1, 0.1, 0.1}), Eigen::Isometry3d::Identity());
  // Along x, overlapping the top face by 1 mm, its ends beyond the face on one side.
  Eigen::Isometry3d T = at3(0.05, 0.0, 0.1 + 0.02 - 0.001);
  T.linear() = Eigen::AngleAxisd(pi / 2, V3::UnitY()).toRotationMatrix();
  Placed c = place(ShapeSpec{"", ShapeType::capsule, Pose{}, {0.02, 0.1, 0.0}}, T);
  const auto cs = contacts(c, b);
  REQUIRE(cs.count == 2);
  for (int i = 0; i < 2; ++i) {
    CHECK(cs.points[static_cast<std::size_t>(i)].separation == Approx(-0.001).margin(1e-9));
    CHECK(cs.points[static_cast<std::size_t>(i)].normal.isApprox(-V3::UnitZ(), 1e-9));
  }
  // The points span the part of the segment over the face: x from -0.05 to 0.1.
  const double x0 = cs.points[0].point.x(), x1 = cs.points[1].point.x();
  CHECK(std::min(x0, x1) == Approx(-0.05).margin(1e-9));
  CHECK(std::max(x0, x1) == Approx(0.1).margin(1e-9));
}

TEST_CASE("capsules against an exact cylinder: side, cap and crossing", "[physics][narrow]") {
  Placed cyl = place(cylinder("", Pose{}, 0.04, 0.1), Eigen::Isometry3d::Identity());
  SECTION("parallel to the side: two points at the radius") {
    Placed c = place(ShapeSpec{"", ShapeType::capsule, Pose{}, {0.01, 0.05, 0.0}},
                     at3(0.0, 0.04 + 0.01 + 0.001, 0.0));
    const auto cs = contacts(c, cyl);
    REQUIRE(cs.count == 2);
    for (int i = 0; i < 2; ++i) {
      CHECK(cs.points[static_cast<std::size_t>(i)].separation == Approx(0.001).margin(1e-9));
      CHECK(cs.points[static_cast<std::size_t>(i)].normal.isApprox(-V3::UnitY(), 1e-9));
    }
  }
  SECTION("lying on the cap: two points clipped to the disc") {
    Eigen::Isometry3d T = at3(0.0, 0.0, 0.1 + 0.01 - 0.002);
    T.linear() = Eigen::AngleAxisd(pi / 2, V3::UnitY()).toRotationMatrix();
    Placed c = place(ShapeSpec{"", ShapeType::capsule, Pose{}, {0.01, 0.1, 0.0}}, T);
    const auto cs = contacts(c, cyl);
    REQUIRE(cs.count == 2);
    CHECK(std::abs(cs.points[0].point.x()) == Approx(0.04).margin(1e-9));
    CHECK(cs.points[0].separation == Approx(-0.002).margin(1e-9));
    CHECK(cs.points[0].normal.isApprox(-V3::UnitZ(), 1e-9));
  }
  SECTION("crossing the side: one point, exact distance") {
    Eigen::Isometry3d T = at3(0.0, 0.06, 0.03);
    T.linear() = Eigen::AngleAxisd(pi / 2, V3::UnitY()).toRotationMatrix();
    Placed c = place(ShapeSpec{"", ShapeType::capsule, Pose{}, {0.015, 0.1, 0.0}}, T);
    const auto cs = contacts(c, cyl);
    REQUIRE(cs.count == 1);
    CHECK(cs.points[0].separation == Approx(0.06 - 0.04 - 0.015).margin(1e-7));
  }
}

TEST_CASE("box pairs: a face gives four points, crossed edges one", "[physics][narrow]") {
  Placed ground = place(box("", Pose{}, {1.0, 1.0, 0.1}), at3(0, 0, -0.1));
  SECTION("a cube resting 1 mm deep") {
    Placed cube = place(box("", Pose{}, {0.05, 0.05, 0.05}), at3(0.2, 0.1, 0.049));
    const auto cs = contacts(ground, cube);
    REQUIRE(cs.count == 4);
    for (int i = 0; i < 4; ++i) {
      CHECK(cs.points[static_cast<std::size_t>(i)].separation == Approx(-0.001).margin(1e-9));
      CHECK(cs.points[static_cast<std::size_t>(i)].normal.isApprox(V3::UnitZ(), 1e-9));
    }
  }
  SECTION("a cube on its edge across another edge") {
    Eigen::Isometry3d Ta = Eigen::Isometry3d::Identity();
    Ta.linear() = Eigen::AngleAxisd(pi / 4, V3::UnitX()).toRotationMatrix();
    Eigen::Isometry3d Tb = at3(0, 0, 0.1 * std::sqrt(2.0) - 0.003);
    Tb.linear() = Eigen::AngleAxisd(pi / 4, V3::UnitY()).toRotationMatrix();
    Placed a = place(box("", Pose{}, {0.05, 0.05, 0.05}), Ta);
    Placed b = place(box("", Pose{}, {0.05, 0.05, 0.05}), Tb);
    const auto cs = contacts(a, b);
    REQUIRE(cs.count == 1);
    CHECK(cs.points[0].separation == Approx(-0.003).margin(1e-9));
    CHECK(cs.points[0].normal.isApprox(V3::UnitZ(), 1e-9));
  }
  SECTION("a cylinder standing on the ground: its prism's cap, reduced to four points") {
    Placed cyl = place(cylinder("", Pose{}, 0.04, 0.1), at3(0, 0, 0.099));
    const auto cs = contacts(ground, cyl);
    REQUIRE(cs.count == 4);
    for (int i = 0; i < 4; ++i)
      CHECK(cs.points[static_cast<std::size_t>(i)].separation == Approx(-0.001).margin(1e-9));
    // Ids stay the same when the cylinder moves a little.
    Placed moved = place(cylinder("", Pose{}, 0.04, 0.1), at3(0.001, 0, 0.0985));
    const auto cs2 = contacts(ground, moved);
    REQUIRE(cs2.count == 4);
    for (int i = 0; i < 4; ++i)
      CHECK(cs2.points[static_cast<std::size_t>(i)].id ==
            cs.points[static_cast<std::size_t>(i)].id);
  }
}
