// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The geometry module: convex primitives in the world, composite objects, signed distances with
/// witness points, a model's link shapes at a configuration, mass properties of shapes.
#pragma once

#include <topograsp/geometry/box_decomposition.hpp>
#include <topograsp/geometry/composite.hpp>
#include <topograsp/geometry/contact.hpp>
#include <topograsp/geometry/mass_properties.hpp>
#include <topograsp/geometry/mesh.hpp>
#include <topograsp/geometry/mesh_simplify.hpp>
#include <topograsp/geometry/model_shapes.hpp>
#include <topograsp/geometry/primitive.hpp>
#include <topograsp/geometry/signed_distance.hpp>
