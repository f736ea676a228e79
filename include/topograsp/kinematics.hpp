// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The kinematics module: forward kinematics and Jacobians, sized at compile time.
#pragma once

#include <topograsp/kinematics/data.hpp>
#include <topograsp/kinematics/forward.hpp>
#include <topograsp/kinematics/jacobian.hpp>
