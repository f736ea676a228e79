// SPDX-License-Identifier: BSD-3-Clause
// Included by every physics test file: the stepper's headers. (EIGEN_RUNTIME_NO_MALLOC, for the
// no-allocation test, is defined for every test executable by tests/CMakeLists.txt.) The hand
// scenes of the tests of closing a hand and the shake test are in tests/evaluation/.
#pragma once

#include <topograsp/physics.hpp>
