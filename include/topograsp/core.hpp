// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The core module: Eigen aliases, poses, constants, errors and status codes.
#pragma once

#include <topograsp/core/cmath.hpp>
#include <topograsp/core/constants.hpp>
#include <topograsp/core/eigen.hpp>
#include <topograsp/core/error.hpp>
#include <topograsp/core/nonnegative_least_squares.hpp>
#include <topograsp/core/pose.hpp>
#include <topograsp/core/status.hpp>
