// SPDX-License-Identifier: BSD-3-Clause
// grasp_transfer --hand barrett: the demonstrations transferred to topograsp::models::barrett_bh8
// (program.hpp).
#include <grasp_transfer/program.hpp>
#include <grasp_transfer/shipped_hands.hpp>
#include <topograsp/model/models/barrett_bh8.hpp>

TOPOGRASP_HAND_PROGRAM("barrett", topograsp::models::barrett_bh8)
