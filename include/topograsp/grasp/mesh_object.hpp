// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Objects from closed triangle meshes (a scanned YCB object): the mesh gives the mass, the
/// centre of mass (the winding reference) and the inertia at a stated density or mass; BADGr's
/// box decomposition of points on its surface gives the convex pieces that both judges collide
/// and measure distance with, and the boxes of the grasp hypotheses.
#pragma once

#include <string>
#include <utility>
#include <vector>

#include <topograsp/core/error.hpp>
#include <topograsp/geometry/box_decomposition.hpp>
#include <topograsp/geometry/mesh.hpp>
#include <topograsp/grasp/object.hpp>

namespace topograsp {

/// The options of mesh_object().
struct MeshObjectOptions {
  /// The spacing (m) of the surface points that BADGr decomposes, also the decomposition's
  /// resolution (BoxDecompositionOptions::resolution is set to it). 4 mm: a box edge is within
  /// about half of it of the points it bounds.
  double spacing = 0.004;
  /// BADGr's splitting rule (volume gain, fewest points per box, planes, depth); its resolution
  /// is replaced by `spacing`.
  BoxDecompositionOptions decomposition{};
};

/// A grasp object from the closed triangle \p mesh (its frame is the object frame, metres):
/// - its mass is \p mass (kg) when positive, else the material's density times the mesh's
///   volume; its centre of mass and inertia are the solid mesh's at that mass (the inertial,
///   GraspObject::inertial: the winding reference is the mesh's centre of mass);
/// - its parts are BADGr's boxes of points on the mesh's surface (box_decomposition(), each box
///   the tight box of its points), the convex pieces that both judges collide with, each of \p
///   material (friction) and of the density that spreads the mass over them (used for nothing else:
///   the inertial overrides it);
/// - its hypothesis boxes are those boxes, each longer than 0.12 m split along its length as for
///   the built-in objects.
/// How far the boxes are from the mesh is decomposition_error(mesh, boxes, spacing).
/// \throws topograsp::invalid_argument naming "mesh" (require_closed_mesh(): what is wrong and
///         where), "mass" (negative or not finite), "material.density" (not positive when the
///         mass is not given), "options.spacing" or "options.decomposition" (box_decomposition());
///         before sampling, "options.spacing" or "mesh" when the surface needs more points than
///         max_surface_points at that spacing ("mesh" when it is larger than 2 m, asking whether
///         it is in millimetres).
[[nodiscard]] inline GraspObject mesh_object(std::string name, const TriangleMesh& mesh,
                                             const Material& material, double mass = 0.0,
                                             const MeshObjectOptions& options = {}) {
  require_closed_mesh(mesh, "mesh");
  require_non_negative(mass, "mass");
  require_positive(options.spacing, "options.spacing");
  detail::require_surface_point_count(mesh, options.spacing, "options.spacing", "mesh");
  require_valid(options.decomposition, "options.decomposition");
  if (mass == 0.0) require_positive(material.density, "material.density");
  const detail::MeshMoments moments = detail::mesh_moments(mesh);
  const double volume = moments.volume;
  const double m = mass > 0.0 ? mass : material.density * volume;
  BoxDecompositionOptions decomposition = options.decomposition;
  decomposition.resolution = options.spacing;
  const std::vector<Vec3> points = surface_points(mesh, options.spacing);
  const std::vector<OrientedBox> boxes = box_decomposition(points, decomposition);
  GraspObject o;
  o.name = std::move(name);
  double box_volume = 0.0;
  for (OrientedBox b : boxes) {
    // The points lie on the surface: the piece is the tight box of its points, without the
    // decomposition's growth by half the spacing (which stands for a point's share of a solid).
    b.half.array() -= 0.5 * decomposition.resolution;
    Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
    T.linear() = b.R;
    T.translation() = b.centre;
    o.parts.push_back(box("", to_pose(T), {b.half.x(), b.half.y(), b.half.z()}));
    box_volume += b.volume();
  }
  for (const ShapeSpec& s : o.parts) {
    o.materials.push_back(material);
    o.densities.push_back(m / box_volume);
    objects::detail::split_box(objects::detail::box_of(s), objects::detail::max_box_length,
                               o.boxes);
  }
  o.mass = m;
  o.inertial = detail::mesh_mass(moments, m / volume);
  o.inertial->mass = m;  // exactly the stated mass
  o.validate();
  return o;
}

}  // namespace topograsp
