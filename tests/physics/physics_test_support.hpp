// SPDX-License-Identifier: BSD-3-Clause
// Included first by every physics test file: it turns on Eigen's run-time allocation check in the
// whole executable (so a no-allocation test can use it without breaking the one-definition rule).
// The hand scenes shared by the tests of closing a hand and the shake test are in
// tests/evaluation/evaluation_test_support.hpp.
#pragma once

#ifndef EIGEN_RUNTIME_NO_MALLOC
#define EIGEN_RUNTIME_NO_MALLOC
#endif

#include <topograsp/physics.hpp>
