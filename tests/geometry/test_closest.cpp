// SPDX-License-Identifier: BSD-3-Clause
// The closest-point kernel shared by geometry and physics (geometry/detail/closest.hpp) against
// closed forms, with the degenerate cases: parallel, anti-parallel, coincident and zero-length
// segments, points on and in boxes and cylinders, and the scalar type float.
#include <cmath>

#include <catch2/catch.hpp>

#include <topograsp/geometry.hpp>
#include <topograsp/geometry/detail/closest.hpp>

using namespace topograsp;

namespace {

struct Params {
  double s = -1.0, t = -1.0;
};

Params params(const Vec3& a0, const Vec3& a1, const Vec3& b0, const Vec3& b1) {
  Params p;
  detail::closest_segment_params<double>(a0, a1, b0, b1, p.s, p.t);
  return p;
}

}  // namespace

TEST_CASE("closest points of crossing segments are where the common perpendicular meets them",
          "[geometry][closest]") {
  // A along x through the origin, B along y at height 1, crossing above x = 0.5.
  const Params p = params({-0.5, 0, 0}, {1.5, 0, 0}, {0.5, -2, 1}, {0.5, 2, 1});
  CHECK(p.s == Approx(0.5));
  CHECK(p.t == Approx(0.5));
  Vec3 ca, cb;
  detail::closest_segment_points<double>({-0.5, 0, 0}, {1.5, 0, 0}, {0.5, -2, 1}, {0.5, 2, 1}, ca,
                                         cb);
  CHECK((ca - Vec3(0.5, 0, 0)).norm() < 1e-15);
  CHECK((cb - Vec3(0.5, 0, 1)).norm() < 1e-15);
}

TEST_CASE("closest points clamp to the segment ends", "[geometry][closest]") {
  // B's line crosses A's beyond A's end: A's end a1 and the foot of the perpendicular on B.
  const Params p = params({0, 0, 0}, {1, 0, 0}, {3, -1, 1}, {3, 1, 1});
  CHECK(p.s == 1.0);
  CHECK(p.t == Approx(0.5));
}

TEST_CASE("parallel overlapping segments meet in the middle of their overlap",
          "[geometry][closest]") {
  // A = [0, 2] on the x axis, B = [1, 3] one unit above: the overlap is x in [1, 2].
  SECTION("same direction") {
    const Params p = params({0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {3, 1, 0});
    CHECK(p.s == Approx(0.75));  // x = 1.5
    CHECK(p.t == Approx(0.25));
  }
  SECTION("opposite directions") {
    const Params p = params({0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 1, 0});
    CHECK(p.s == Approx(0.75));
    CHECK(p.t == Approx(0.75));
  }
  SECTION("swapping the segments gives the same points") {
    const Params p = params({1, 1, 0}, {3, 1, 0}, {0, 0, 0}, {2, 0, 0});
    CHECK(p.s == Approx(0.25));
    CHECK(p.t == Approx(0.75));
  }
  SECTION("B inside A's span") {
    const Params p = params({0, 0, 0}, {4, 0, 0}, {1, 0, 1}, {2, 0, 1});
    CHECK(p.s == Approx(0.375));  // x = 1.5
    CHECK(p.t == Approx(0.5));
  }
  SECTION("nearly parallel (1e-7 rad) counts as parallel") {
    const Params p = params({0, 0, 0}, {2, 0, 0}, {1, 1, 0}, {3, 1 + 2e-7, 0});
    CHECK(p.s == Approx(0.75));
    CHECK(p.t == Approx(0.25).margin(1e-6));
  }
}

TEST_CASE("parallel segments whose projections are disjoint meet at their nearest ends",
          "[geometry][closest]") {
  const Params p = params({0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {3, 1, 0});
  CHECK(p.s == 1.0);
  CHECK(p.t == 0.0);
  const Params q = params({0, 0, 0}, {1, 0, 0}, {-3, 1, 0}, {-2, 1, 0});
  CHECK(q.s == 0.0);
  CHECK(q.t == 1.0);
}

TEST_CASE("coincident segments meet in the middle", "[geometry][closest]") {
  const Params p = params({0, 0, 0}, {1, 0, 0}, {0, 0, 0}, {1, 0, 0});
  CHECK(p.s == Approx(0.5));
  CHECK(p.t == Approx(0.5));
  // Collinear and overlapping by [0.5, 1]: the middle, 0.75, on both.
  const Params q = params({0, 0, 0}, {1, 0, 0}, {0.5, 0, 0}, {1.5, 0, 0});
  CHECK(q.s == Approx(0.75));
  CHECK(q.t == Approx(0.25));
}

TEST_CASE("zero-length segments are points", "[geometry][closest]") {
  SECTION("both") {
    const Params p = params({1, 2, 3}, {1, 2, 3}, {0, 0, 0}, {0, 0, 0});
    CHECK(p.s == 0.0);
    CHECK(p.t == 0.0);
  }
  SECTION("A: the foot of the perpendicular on B, clamped") {
    CHECK(params({0.3, 1, 0}, {0.3, 1, 0}, {0, 0, 0}, {1, 0, 0}).t == Approx(0.3));
    CHECK(params({2, 1, 0}, {2, 1, 0}, {0, 0, 0}, {1, 0, 0}).t == 1.0);
    CHECK(params({-2, 1, 0}, {-2, 1, 0}, {0, 0, 0}, {1, 0, 0}).t == 0.0);
  }
  SECTION("B: the foot of the perpendicular on A, clamped") {
    const Params p = params({0, 0, 0}, {2, 0, 0}, {0.5, -1, 0}, {0.5, -1, 0});
    CHECK(p.s == Approx(0.25));
    CHECK(p.t == 0.0);
  }
  SECTION("shorter than 1e-9 counts as a point") {
    const Params p = params({0, 0, 0}, {1e-10, 0, 0}, {0.5, 1, 0}, {0.5, -1, 0});
    CHECK(p.s == 0.0);
    CHECK(p.t == Approx(0.5));
  }
}

TEST_CASE("the kernel runs in float", "[geometry][closest]") {
  using V = Vec<3, float>;
  float s = -1.0f, t = -1.0f;
  detail::closest_segment_params<float>(V(0, 0, 0), V(2, 0, 0), V(1, 1, 0), V(3, 1, 0), s, t);
  CHECK(s == Approx(0.75f));
  CHECK(t == Approx(0.25f));
}

TEST_CASE("any_perpendicular and tangent_basis give orthonormal right-handed frames",
          "[geometry][closest]") {
  const Vec3 dirs[] = {Vec3::UnitX(),       Vec3::UnitY(),         Vec3::UnitZ(),
                       -Vec3::UnitZ(),      Vec3(1, 2, 3),         Vec3(-0.3, 0.1, -5),
                       Vec3(1e-3, 0, -1.0), Vec3(0.57, 0.57, 0.57)};
  for (const Vec3& d : dirs) {
    const Vec3 u = detail::any_perpendicular<double>(d);
    CHECK(std::abs(u.norm() - 1.0) < 1e-14);
    CHECK(std::abs(u.dot(d.normalized())) < 1e-14);
    Vec3 t1, t2;
    const Vec3 n = d.normalized();
    detail::tangent_basis<double>(n, t1, t2);
    CHECK(std::abs(t1.norm() - 1.0) < 1e-14);
    CHECK(std::abs(t2.norm() - 1.0) < 1e-14);
    CHECK(std::abs(t1.dot(t2)) < 1e-14);
    CHECK((t1.cross(t2) - n).norm() < 1e-14);
    CHECK(u == t1);  // the same construction
  }
  CHECK(detail::any_perpendicular<double>(Vec3::Zero()) == Vec3::UnitZ());
}

TEST_CASE("closest points of a box and a cylinder in their own axes", "[geometry][closest]") {
  bool inside = false;
  const Vec3 h(1, 2, 3);
  CHECK(detail::closest_on_box<double>(h, Vec3(5, -1, 4), inside) == Vec3(1, -1, 3));
  CHECK_FALSE(inside);
  CHECK(detail::closest_on_box<double>(h, Vec3(0.5, -1, 2), inside) == Vec3(0.5, -1, 2));
  CHECK(inside);
  CHECK(detail::closest_on_box<double>(h, Vec3(1, 2, 3), inside) == Vec3(1, 2, 3));
  CHECK(inside);  // on the surface counts as in
  // Cylinder of radius 1, half height 2.
  const Vec3 side = detail::closest_on_cylinder<double>(1.0, 2.0, Vec3(3, 4, 1), inside);
  CHECK((side - Vec3(0.6, 0.8, 1)).norm() < 1e-15);
  CHECK_FALSE(inside);
  const Vec3 rim = detail::closest_on_cylinder<double>(1.0, 2.0, Vec3(0, 2, -5), inside);
  CHECK((rim - Vec3(0, 1, -2)).norm() < 1e-15);
  CHECK_FALSE(inside);
  const Vec3 cap = detail::closest_on_cylinder<double>(1.0, 2.0, Vec3(0.5, 0, 3), inside);
  CHECK(cap == Vec3(0.5, 0, 2));
  CHECK_FALSE(inside);
  CHECK(detail::closest_on_cylinder<double>(1.0, 2.0, Vec3(0.5, 0, 1), inside) == Vec3(0.5, 0, 1));
  CHECK(inside);
}

TEST_CASE("signed distance of a point to a posed box and cylinder", "[geometry][closest]") {
  const Mat3 R = Eigen::AngleAxisd(0.5, Vec3::UnitZ()).toRotationMatrix();
  const Vec3 p(1, 2, 3);
  // Outside a face of the box (half extents 1, 2, 3), 0.5 beyond +x.
  const detail::PointSolid f =
      detail::point_box<double>(p + R * Vec3(1.5, 0.5, 0), R, p, Vec3(1, 2, 3));
  CHECK(f.sd == Approx(0.5));
  CHECK((f.n - R.col(0)).norm() < 1e-14);
  CHECK((f.y - (p + R * Vec3(1, 0.5, 0))).norm() < 1e-14);
  // Inside, nearest to the -y face.
  const detail::PointSolid in =
      detail::point_box<double>(p + R * Vec3(0, -1.8, 0), R, p, Vec3(1, 2, 3));
  CHECK(in.sd == Approx(-0.2));
  CHECK((in.n + R.col(1)).norm() < 1e-14);
  // Cylinder of radius 1, half height 2: beyond the rim, diagonally.
  const detail::PointSolid c =
      detail::point_cylinder<double>(p + R * Vec3(0, 4, 6), R, p, 1.0, 2.0);
  CHECK(c.sd == Approx(5.0));  // (3, 4) from the rim point (0, 1, 2)
  CHECK((c.y - (p + R * Vec3(0, 1, 2))).norm() < 1e-14);
  // Inside, nearer the side (0.2) than the caps (1.5).
  const detail::PointSolid cs =
      detail::point_cylinder<double>(p + R * Vec3(0.8, 0, 0.5), R, p, 1.0, 2.0);
  CHECK(cs.sd == Approx(-0.2));
  CHECK((cs.n - R.col(0)).norm() < 1e-14);
}

TEST_CASE("two parallel capsules' witness points are in the middle of their overlap",
          "[geometry][closest]") {
  const Primitive a = Primitive::capsule({0, 0, 0}, {2, 0, 0}, 0.1);
  const Primitive b = Primitive::capsule({1, 1, 0}, {3, 1, 0}, 0.1);
  const Contact c = signed_distance(a, b);
  CHECK(c.distance == Approx(0.8));
  CHECK((c.point_a - Vec3(1.5, 0.1, 0)).norm() < 1e-12);
  CHECK((c.point_b - Vec3(1.5, 0.9, 0)).norm() < 1e-12);
  CHECK((c.normal - Vec3::UnitY()).norm() < 1e-12);
}
