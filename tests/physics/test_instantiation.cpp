// SPDX-License-Identifier: BSD-3-Clause
// Explicit instantiations: every member of the stepper compiles for both scalar types. (The hand
// scene's are in tests/evaluation/test_no_alloc.cpp.)
#include "physics_test_support.hpp"

template class topograsp::World<double>;
template class topograsp::World<float>;
