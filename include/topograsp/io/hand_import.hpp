// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Hands from URDF and MJCF files: import_hand_file() reads a robot description into the pieces a
/// model is written from (links with their joints, collision shapes, frames; model/spec.hpp) and
/// model_header() writes them as a C++ header of constexpr arrays, which make_model() then checks
/// and resolves while the user's code compiles, like a hand written out by hand. The tool
/// topograsp_import_hand and the CMake function topograsp_import_hand() run this at build time
/// (docs/models.md, "Bring your own hand").
///
/// What a file cannot say (which chains are the thumb and the fingers, where the palm centre and
/// the fingertips are, which way each joint closes) the user adds in a few lines of C++ that name
/// the file's links (docs/models.md).
///
/// Supported: URDF links, revolute / continuous / prismatic / fixed joints with origins, axes,
/// limits (effort is the torque limit, velocity the speed limit), <mimic>, inertial mass and
/// centre, collision box / cylinder / sphere / mesh. MJCF (MuJoCo 2.x): nested bodies with pos and
/// any orientation (quat, axisangle, euler with the compiler's eulerseq, xyaxes, zaxis), hinge and
/// slide joints (several per body, away from the body origin), ranges in the compiler's angle
/// unit, default classes and childclass, geoms box / capsule / cylinder / sphere / ellipsoid /
/// mesh (fromto included; geoms with contype and conaffinity 0 are visual and left out), sites,
/// <equality><joint> couplings of degree 1, actuators on joints and on fixed tendons with their
/// force ranges and gears, inertial mass and centre. Mesh geoms become the box bounding the mesh
/// (STL or OBJ) in the geom's frame; an ellipsoid becomes the capsule around it along its longest
/// axis. Everything approximated or left out is listed in ImportedHand::notes and in the header.
#pragma once

#include <string>

#include <topograsp/core/error.hpp>
#include <topograsp/io/hand_import/checks.hpp>
#include <topograsp/io/hand_import/common.hpp>
#include <topograsp/io/hand_import/header_writer.hpp>
#include <topograsp/io/hand_import/mjcf.hpp>
#include <topograsp/io/hand_import/urdf.hpp>
#include <topograsp/io/xml.hpp>

namespace topograsp {

/// Imports a URDF (<robot>) or MJCF (<mujoco>) document \p doc, read from the file doc.file.
/// What it returns, make_model() accepts (with a hand description that names existing links).
/// \throws topograsp::import_error naming the file, the line, the element and the problem, for
/// anything the model cannot hold (the list in this file's comment); or naming the file and the
/// link, shape or frame for what make_model() would refuse (a name used twice, a coupling to a
/// coupled joint, numbers beyond the model's ranges).
[[nodiscard]] inline ImportedHand import_hand(const XmlDocument& doc,
                                              const ImportOptions& options = {}) {
  if (doc.root.name == "robot" || doc.root.name == "mujoco") {
    ImportedHand hand = doc.root.name == "robot" ? detail::import_urdf(doc, options)
                                                 : detail::import_mjcf(doc, options);
    detail::check_importable(hand);
    return hand;
  }
  throw import_error(doc.file + ":" + std::to_string(doc.root.line) + ": <" + doc.root.name +
                     ">: neither a URDF file (<robot>) nor an MJCF file (<mujoco>)");
}

/// Reads and imports the URDF or MJCF file at \p path (the format from its root element).
/// \throws topograsp::xml_error for a file that cannot be read or is not well-formed XML,
/// topograsp::import_error for one that cannot be imported.
[[nodiscard]] inline ImportedHand import_hand_file(const std::string& path,
                                                   const ImportOptions& options = {}) {
  return import_hand(read_xml_file(path), options);
}

}  // namespace topograsp
