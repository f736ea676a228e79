// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The render module: SVG scene renderings, SVG line plots and the self-contained results page.
#pragma once

#include <topograsp/render/html_page.hpp>
#include <topograsp/render/svg_camera.hpp>
#include <topograsp/render/svg_panels.hpp>
#include <topograsp/render/svg_plot.hpp>
#include <topograsp/render/svg_scene.hpp>
