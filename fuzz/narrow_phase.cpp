// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: the narrow phase, collide() of physics/narrow_phase.hpp, on two shapes built as the
// stepper builds them (a ShapeView with the box's or cylinder's polytope), in double or float.
//
// The inputs are bounded to the stepper's working range: sizes in [1 mm, 2 m] (a capsule's half
// length may be 0), centres within 3 m of the origin, any rotation, a margin in [0, 1 cm].
// For every contact: the point, normal and separation are finite, the normal has unit length,
// the separation is at most the margin. Against the exact signed distance d of the two shapes
// (geometry's signed_distance(), in double; the prism that stands in for a cylinder lies inside
// it, so its distance is never smaller):
// - shapes with d clearly above the margin get no contact;
// - no contact claims a deeper overlap than d, within twice the polytope collider's preference
//   for face axes (0.2 mm + 10 % of the depth), except where a sphere's or capsule's core is
//   inside a box or cylinder and for pairs with a cylinder (not yet compared, see below);
// - separated shapes (d > 0) get normals that point from A towards B (positive along d's normal),
//   except for a cylinder's prism against a box or prism, whose faces differ from the cylinder.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include <topograsp/geometry/signed_distance.hpp>
#include <topograsp/physics/narrow_phase.hpp>

#include "fuzz_input.hpp"

namespace {

using topograsp::ShapeType;
using namespace topograsp::fuzz;

struct Shape {
  ShapeType type = ShapeType::sphere;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  Eigen::Vector3d p = Eigen::Vector3d::Zero(), size = Eigen::Vector3d::Zero();
};

Shape read_shape(FuzzInput& in) {
  Shape s;
  s.type = in.pick({ShapeType::sphere, ShapeType::capsule, ShapeType::box, ShapeType::cylinder});
  s.R = in.rotation();
  s.p = in.vec(-3.0, 3.0);
  const double a = in.real(1e-3, 2.0), b = in.real(1e-3, 2.0), c = in.real(1e-3, 2.0);
  switch (s.type) {
    case ShapeType::sphere:
      s.size = {a, 0.0, 0.0};
      break;
    case ShapeType::capsule:
      s.size = {a, in.flag() ? 0.0 : b, 0.0};
      break;
    case ShapeType::box:
      s.size = {a, b, c};
      break;
    case ShapeType::cylinder:
      s.size = {a, b, 0.0};
      break;
  }
  return s;
}

std::string describe(const Shape& s, const char* name) {
  return std::string(name) + ": " + std::string(to_string(s.type)) + ", size " + vec_str(s.size) +
         ", p " + vec_str(s.p) + ", R " + mat_str(s.R) + "\n";
}

topograsp::Primitive primitive(const Shape& s) {
  topograsp::Primitive q;
  q.type = s.type;
  q.R = s.R;
  q.p = s.p;
  q.size = s.size;
  return q;
}

template <class S>
void run(const Shape& a, const Shape& b, double margin, const std::string& input) {
  const auto polytope = [](const Shape& s) {
    if (s.type == ShapeType::box) return topograsp::box_polytope<S>(s.size.template cast<S>());
    if (s.type == ShapeType::cylinder)
      return topograsp::cylinder_polytope<S>(static_cast<S>(s.size[0]), static_cast<S>(s.size[1]));
    return topograsp::Polytope<S>{};
  };
  const topograsp::Polytope<S> pa = polytope(a), pb = polytope(b);
  const auto view = [](const Shape& s, const topograsp::Polytope<S>& poly) {
    topograsp::ShapeView<S> v;
    v.type = s.type;
    v.R = s.R.template cast<S>();
    v.p = s.p.template cast<S>();
    v.size = s.size.template cast<S>();
    v.polytope = topograsp::detail::is_rounded(s.type) ? nullptr : &poly;
    return v;
  };
  topograsp::ContactSet<S> out;
  topograsp::collide<S>(view(a, pa), view(b, pb), static_cast<S>(margin), out);

  // The exact signed distance of the shapes as the stepper sees them (rounded to S).
  Shape as = a, bs = b;
  as.R = a.R.template cast<S>().template cast<double>();
  as.p = a.p.template cast<S>().template cast<double>();
  bs.R = b.R.template cast<S>().template cast<double>();
  bs.p = b.p.template cast<S>().template cast<double>();
  const topograsp::Contact exact = topograsp::signed_distance(primitive(as), primitive(bs));
  const double d = exact.distance;
  // Rounding: S's epsilon at the scene's size (5 m) a hundredfold, at least 1 nm (cylinders'
  // distances are iterative in signed_distance()).
  const double tol =
      std::max(1e-9, 100.0 * 5.0 * static_cast<double>(std::numeric_limits<S>::epsilon()));
  const bool polytope_prism = !topograsp::detail::is_rounded(a.type) &&
                              !topograsp::detail::is_rounded(b.type) &&
                              (a.type == ShapeType::cylinder || b.type == ShapeType::cylinder);

  // A sphere's or capsule's core (point, segment) inside a box or cylinder leaves it by the
  // shallowest face, cap or side (collide_rounded.hpp), not along the exact depth: not compared.
  const double round =
      topograsp::detail::is_rounded(a.type) != topograsp::detail::is_rounded(b.type)
          ? (topograsp::detail::is_rounded(a.type) ? a.size[0] : b.size[0])
          : 0.0;
  const bool core_inside = round > 0.0 && d < -round;
  // With a cylinder the depths are not compared. signed_distance's EPA used to fail on them
  // (fuzz/regressions/narrow_phase/epa_unconverged_cylinder_depth, docs/testing.md); it is now
  // within 1e-10 (1 + depth) m, or 3e-5 of the depth where it runs out of vertices, but the
  // comparison has not been re-enabled and run (two prisms also skip their cap-edge by cap-edge
  // axes in collide_polytopes.hpp).
  const bool with_cylinder = a.type == ShapeType::cylinder || b.type == ShapeType::cylinder;
  // The polytope collider keeps a face axis unless an edge axis is better by 1e-4 m + 5 % of the
  // depth (for stable face contacts): twice that is allowed.
  const double depth_slack = tol + 2e-4 + 0.1 * std::abs(d);
  const std::string info = input + "margin = " + num(margin) + "\nsigned distance = " + num(d) +
                           ", normal " + vec_str(exact.normal) +
                           "\ncontacts: " + std::to_string(out.count) + "\n";
  if (out.count < 0 || out.count > 4)
    fuzz_fail("narrow_phase", "contact count " + std::to_string(out.count), info);
  if (out.count > 0 && d > margin + tol)
    fuzz_fail("narrow_phase",
              "a contact for shapes " + num(d) + " m apart (margin " + num(margin) + ")", info);
  for (int k = 0; k < out.count; ++k) {
    const topograsp::ContactFeature<S>& c = out.points[static_cast<std::size_t>(k)];
    const std::string which = "contact " + std::to_string(k) + " (point " +
                              vec_str(c.point.template cast<double>()) + ", normal " +
                              vec_str(c.normal.template cast<double>()) + ", separation " +
                              num(static_cast<double>(c.separation)) + "): ";
    if (!c.point.allFinite() || !c.normal.allFinite() || !std::isfinite(c.separation))
      fuzz_fail("narrow_phase", which + "not finite", info);
    const double len = static_cast<double>(c.normal.norm());
    if (!(std::abs(len - 1.0) <= 1e2 * static_cast<double>(std::numeric_limits<S>::epsilon())))
      fuzz_fail("narrow_phase", which + "normal of length " + num(len), info);
    const double sep = static_cast<double>(c.separation);
    if (!(sep <= margin + tol))
      fuzz_fail("narrow_phase", which + "separation above the margin", info);
    if (!core_inside && !with_cylinder && !(sep >= d - depth_slack))
      fuzz_fail("narrow_phase", which + "deeper than the shapes' overlap " + num(d), info);
    if (d > tol && !polytope_prism && !(c.normal.template cast<double>().dot(exact.normal) > 0.0))
      fuzz_fail("narrow_phase", which + "normal points from B towards A", info);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return topograsp::fuzz::run_input(data, size, [&] {
    FuzzInput in(data, size);
    const bool single = in.flag();
    const Shape a = read_shape(in), b = read_shape(in);
    const double margin = in.real(0.0, 0.01);
    const std::string input = std::string("scalar: ") + (single ? "float" : "double") + "\n" +
                              describe(a, "A") + describe(b, "B");
    if (single)
      run<float>(a, b, margin, input);
    else
      run<double>(a, b, margin, input);
  });
}
