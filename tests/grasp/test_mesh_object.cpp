// SPDX-License-Identifier: BSD-3-Clause
// Objects from meshes (grasp/mesh_object.hpp): the mesh's mass properties carried to the scene,
// BADGr's boxes as the collision pieces and hypothesis boxes, and what bad input gives.
#include <cmath>
#include <limits>

#include <catch2/catch.hpp>

#include <topograsp/grasp/human_grasps.hpp>
#include <topograsp/grasp/hypothesis.hpp>
#include <topograsp/grasp/mesh_object.hpp>

#include "support/meshes.hpp"
#include "support/throws.hpp"

using namespace topograsp;

TEST_CASE("a mesh can has the mesh's mass properties and BADGr's boxes", "[grasp][mesh]") {
  // A 0.33 l drink can: r 0.033 m, 0.115 m tall, 0.356 kg, its circles as 48-gons.
  const TriangleMesh can = test::cylinder_mesh(0.033, 0.115, 48);
  const GraspObject o = mesh_object("mesh_can", can, materials::aluminium, 0.356);
  CHECK(o.name == "mesh_can");
  CHECK(o.mass == 0.356);
  REQUIRE(o.inertial.has_value());
  CHECK(o.inertial->mass == 0.356);
  // The centre of mass is the mesh's: on the axis, half way up.
  CHECK(o.centre_of_mass().isApprox(Vec3(0, 0, 0.0575), 1e-9));
  // The inertia of the 48-gon prism is the cylinder's within 0.3 % (area ratio of the n-gon).
  const double m = 0.356, r = 0.033, h = 0.115;
  CHECK(o.inertial->inertia(2, 2) == Approx(0.5 * m * r * r).epsilon(3e-3));
  CHECK(o.inertial->inertia(0, 0) == Approx(m * (3 * r * r + h * h) / 12).epsilon(3e-3));
  // Every part is a box of aluminium; the boxes stand for the can within a few mm.
  REQUIRE_FALSE(o.parts.empty());
  for (const ShapeSpec& s : o.parts) CHECK(s.type == ShapeType::box);
  CHECK(o.materials.size() == o.parts.size());
  CHECK(o.materials.front().surface == Surface::aluminium);
  std::vector<OrientedBox> boxes;
  for (const ShapeSpec& s : o.parts)
    boxes.push_back(
        {s.pose.rotation(), s.pose.translation(), Vec3(s.size[0], s.size[1], s.size[2])});
  const DecompositionError e = decomposition_error(can, boxes, 0.004);
  INFO("volume ratio " << e.volume_ratio << ", mean " << e.mean_distance << ", max "
                       << e.max_distance);
  CHECK(e.volume_ratio > 1.0);
  CHECK(e.volume_ratio < 4.0 / pi + 0.02);  // at most the one box around a cylinder
  CHECK(e.mean_distance < 0.006);
  CHECK(e.max_distance < 0.012);
  // The hypotheses come from the same boxes: four per reachable face.
  CHECK_FALSE(o.boxes.empty());
  CHECK(box_hypotheses(o).size() >= 4 * o.boxes.size());
  // Without a mass: the material's density times the mesh's volume (the boxes are not what this
  // checks: a coarse spacing keeps the decomposition cheap).
  MeshObjectOptions coarse;
  coarse.spacing = 0.02;
  const GraspObject solid = mesh_object("solid", can, materials::aluminium, 0.0, coarse);
  const double volume = mesh_mass_properties(can, 1.0).mass;
  CHECK(solid.mass == Approx(2700.0 * volume).epsilon(1e-12));
  CHECK(volume == Approx(pi * r * r * h).epsilon(3e-3));
}

TEST_CASE("the scene holds a mesh object by the mesh's mass properties", "[grasp][mesh]") {
  // An L of two boxes as one closed mesh would need a union; a box mesh off its frame's origin
  // shows the centre of mass carried through: [0, 0.06] x [0, 0.04] x [0, 0.2].
  const GraspObject o = mesh_object("bar", test::box_mesh(0.06, 0.04, 0.2), materials::hickory);
  const ObjectSpec spec = object_spec(o, HandSurface::human_skin);
  REQUIRE(spec.inertial.has_value());
  CHECK(spec.inertial->com.isApprox(Vec3(0.03, 0.02, 0.1), 1e-12));
  World<double> w;
  BodyDesc d;
  d.shapes = spec.shapes;
  d.inertial = spec.inertial;
  const int b = w.add_body(d);
  CHECK(w.body(b).mass == Approx(800.0 * 0.06 * 0.04 * 0.2).epsilon(1e-12));
  CHECK(w.body(b).local_com.isApprox(Vec3(0.03, 0.02, 0.1), 1e-12));
  // One box: the mesh is a box, so BADGr keeps it whole, the tight box of its surface points.
  REQUIRE(o.parts.size() == 1);
  CHECK(o.parts[0].size[0] * o.parts[0].size[1] * o.parts[0].size[2] ==
        Approx(0.03 * 0.02 * 0.1).epsilon(5e-3));
}

TEST_CASE("mesh_object refuses bad input naming it", "[grasp][mesh][bad-input]") {
  const TriangleMesh can = test::cylinder_mesh(0.033, 0.115, 16);
  TriangleMesh open = can;
  open.triangles.pop_back();
  CHECK_THROWS_WITH(mesh_object("o", open, materials::pet),
                    Catch::StartsWith("mesh: ") && Catch::Contains("the mesh is open"));
  CHECK_THROWS_WITH(mesh_object("o", can, materials::pet, -1.0), Catch::StartsWith("mass: "));
  CHECK_THROWS_WITH(mesh_object("o", can, materials::pet, std::numeric_limits<double>::infinity()),
                    Catch::StartsWith("mass: "));
  Material airy = materials::pet;
  airy.density = 0.0;
  CHECK_THROWS_WITH(mesh_object("o", can, airy), Catch::StartsWith("material.density: "));
  // The objects this test makes are not what it checks: a coarse spacing keeps their
  // decompositions cheap (under the sanitizers they took a minute at the default).
  MeshObjectOptions coarse;
  coarse.spacing = 0.02;
  CHECK_NOTHROW(mesh_object("o", can, airy, 0.2, coarse));  // a given mass needs no density
  MeshObjectOptions bad;
  bad.spacing = 0.0;
  CHECK_THROWS_WITH(mesh_object("o", can, materials::pet, 0.2, bad),
                    Catch::StartsWith("options.spacing: "));
  bad = {};
  bad.decomposition.gain = 1.5;
  CHECK_THROWS_WITH(mesh_object("o", can, materials::pet, 0.2, bad),
                    Catch::StartsWith("options.decomposition: "));
  // A GraspObject whose inertial disagrees with its mass is refused by validate().
  GraspObject o = mesh_object("o", can, materials::pet, 0.2, coarse);
  o.inertial->mass = 0.3;
  CHECK_THROWS_WITH(o.validate(), Catch::StartsWith("o.inertial.mass: "));
}

TEST_CASE("mesh_object refuses a mesh or spacing that needs too many surface points",
          "[grasp][mesh][bad-input]") {
  // The count is known before sampling: exactly what surface_points() returns.
  const TriangleMesh can = test::cylinder_mesh(0.033, 0.115, 16);
  CHECK(surface_point_count(can, 0.004) == static_cast<double>(surface_points(can, 0.004).size()));
  CHECK(surface_point_count(can, 0.001) == static_cast<double>(surface_points(can, 0.001).size()));
  // A 1 km cube and a 10 cm cube written in millimetres (100 m) sampled points until
  // std::bad_alloc; now they are refused before sampling, naming the mesh, with the count, the
  // limit and a hint about the unit.
  for (const double side : {1000.0, 100.0}) {
    INFO("side " << side);
    CHECK_THROWS_WITH(
        mesh_object("o", test::box_mesh(side, side, side), materials::pet, 1.0),
        Catch::StartsWith("mesh: sampling its surface (") &&
            Catch::Contains("every 0.004 m needs") &&
            Catch::Contains("points, more than the limit of 4e+06 (max_surface_points)") &&
            Catch::EndsWith("is the mesh in millimetres? scale it by 0.001"));
  }
  CHECK_THROWS_WITH(mesh_object("o", test::box_mesh(100, 100, 100), materials::pet, 1.0),
                    Catch::Contains("(60000 m^2, bounding box 100 x 100 x 100 m)"));
  // A spacing of 1e-6 m on a drink can: refused naming the option, no unit hint.
  MeshObjectOptions fine;
  fine.spacing = 1e-6;
  CHECK_THROWS_WITH(mesh_object("o", can, materials::pet, 0.2, fine),
                    Catch::StartsWith("options.spacing: sampling the mesh's surface (") &&
                        Catch::Contains("every 1e-06 m needs") &&
                        Catch::Contains("more than the limit of 4e+06") &&
                        !Catch::Contains("millimetres"));
  // surface_points() itself refuses, naming its own argument.
  CHECK_THROWS_WITH(surface_points(can, 1e-6), Catch::StartsWith("spacing: "));
  CHECK_THROWS_WITH(surface_points(test::box_mesh(1000, 1000, 1000), 0.004),
                    Catch::StartsWith("mesh: "));
  // A 1 m cube (a large object) at the default spacing is inside the limit.
  CHECK(surface_point_count(test::box_mesh(1, 1, 1), 0.004) < max_surface_points / 4);
}
