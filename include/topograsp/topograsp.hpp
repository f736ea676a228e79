// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Everything in topograsp. Each module also has its own umbrella header
/// (<topograsp/model.hpp>, <topograsp/kinematics.hpp>, ...) and can be used on its own.
#pragma once

#include <topograsp/aico.hpp>
#include <topograsp/core.hpp>
#include <topograsp/evaluation.hpp>
#include <topograsp/geometry.hpp>
#include <topograsp/grasp.hpp>
#include <topograsp/io.hpp>
#include <topograsp/kinematics.hpp>
#include <topograsp/model.hpp>
#include <topograsp/physics.hpp>
#include <topograsp/render.hpp>
#include <topograsp/task.hpp>
