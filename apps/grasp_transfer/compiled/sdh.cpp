// SPDX-License-Identifier: BSD-3-Clause
// topograsp::models::schunk_sdh's transfer steps and its paper setting (transfer(),
// transfer_shuffled()), compiled once for the programs and the tests (shipped_hands.hpp).
#include <grasp_transfer/shipped_hands.hpp>

TOPOGRASP_COMPILE_HAND(topograsp::models::schunk_sdh);
TOPOGRASP_SDH_SETTING();
