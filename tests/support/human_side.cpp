// SPDX-License-Identifier: BSD-3-Clause
// The human hand's side (demonstrate(), demonstrate_recorded()) compiled once for the test modules
// that call it (any_hand, apps, grasp), which declare it compiled here
// (TOPOGRASP_EXTERN_HUMAN_DEMONSTRATIONS, tests/CMakeLists.txt).
#include <topograsp/grasp/human_side.hpp>
