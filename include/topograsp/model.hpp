// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The model module: constexpr kinematic trees, their checks, compositions and the shipped models.
#pragma once

#include <topograsp/model/compose.hpp>
#include <topograsp/model/model.hpp>
#include <topograsp/model/models.hpp>
#include <topograsp/model/spec.hpp>
