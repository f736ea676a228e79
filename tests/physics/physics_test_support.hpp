// SPDX-License-Identifier: BSD-3-Clause
// Included first by every physics test file. It defines EIGEN_RUNTIME_NO_MALLOC for the whole
// executable, as tests/evaluation does, so that every test of the stepper compiles the same Eigen
// (the one-definition rule) whether or not a test turns the allocation check on. The hand scenes
// shared by the tests of closing a hand and the shake test, and the no-allocation test, are in
// tests/evaluation/.
#pragma once

#ifndef EIGEN_RUNTIME_NO_MALLOC
#define EIGEN_RUNTIME_NO_MALLOC
#endif

#include <topograsp/physics.hpp>
