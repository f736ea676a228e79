// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The kinematics module: forward kinematics and Jacobians, sized at compile time, and the bounded
/// least-squares fit of a configuration.
#pragma once

#include <topograsp/kinematics/data.hpp>
#include <topograsp/kinematics/forward.hpp>
#include <topograsp/kinematics/jacobian.hpp>
#include <topograsp/kinematics/least_squares.hpp>
