// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The io module: JSON results, MJCF export, SVG plots and scene renderings, the results page.
#pragma once

#include <topograsp/io/html_page.hpp>
#include <topograsp/io/journal.hpp>
#include <topograsp/io/json.hpp>
#include <topograsp/io/keypoint_grasp.hpp>
#include <topograsp/io/mesh_file.hpp>
#include <topograsp/io/mesh_write.hpp>
#include <topograsp/io/mjcf.hpp>
#include <topograsp/io/report.hpp>
#include <topograsp/io/results.hpp>
#include <topograsp/io/svg_plot.hpp>
#include <topograsp/io/svg_scene.hpp>
#include <topograsp/io/ycb_objects.hpp>
