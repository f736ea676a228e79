// SPDX-License-Identifier: BSD-3-Clause
// topograsp::models::shadow_hand's transfer steps, compiled once for the programs and the tests
// (shipped_hands.hpp).
#include <grasp_transfer/shipped_hands.hpp>

TOPOGRASP_COMPILE_HAND(topograsp::models::shadow_hand);
