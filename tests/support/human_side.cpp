// SPDX-License-Identifier: BSD-3-Clause
// The human hand's side (demonstrate(), demonstrate_recorded()) compiled once for every test
// module, which declares it compiled here (TOPOGRASP_EXTERN_HUMAN_DEMONSTRATIONS,
// tests/CMakeLists.txt).
#include <topograsp/grasp/human_side.hpp>
