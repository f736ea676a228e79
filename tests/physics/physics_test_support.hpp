// SPDX-License-Identifier: BSD-3-Clause
// Included by every physics test file: the stepper's headers and the constants the tests share
// (one definition each, for the module's unity build). (EIGEN_RUNTIME_NO_MALLOC, for the
// no-allocation test, is defined for every test executable by tests/CMakeLists.txt.) The hand
// scenes of the tests of closing a hand and the shake test are in tests/evaluation/.
#pragma once

#include <topograsp/physics.hpp>

namespace topograsp::test {

/// Standard gravity (m/s^2), the g of the tests' closed forms.
inline constexpr double g = standard_gravity;

}  // namespace topograsp::test
