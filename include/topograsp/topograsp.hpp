// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// Everything in topograsp. Each module also has its own umbrella header
/// (<topograsp/model.hpp>, <topograsp/kinematics.hpp>, ...) and can be used on its own.
#pragma once

#include <topograsp/core.hpp>
#include <topograsp/kinematics.hpp>
#include <topograsp/model.hpp>
