// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The io module: file formats. JSON, meshes (OBJ, STL, PLY), keypoint recordings, MJCF export,
/// the YCB objects' files and the atomic text file writer. (Hand import from URDF and MJCF,
/// io/hand_import.hpp, is included by the import tool only.)
#pragma once

#include <topograsp/io/json.hpp>
#include <topograsp/io/json_schema.hpp>
#include <topograsp/io/keypoint_grasp.hpp>
#include <topograsp/io/mesh_file.hpp>
#include <topograsp/io/mesh_write.hpp>
#include <topograsp/io/mjcf.hpp>
#include <topograsp/io/text_file.hpp>
#include <topograsp/io/ycb_objects.hpp>
