// SPDX-License-Identifier: BSD-3-Clause
// grasp_transfer --hand shadow: the demonstrations transferred to topograsp::models::shadow_hand
// (program.hpp).
#include <grasp_transfer/program.hpp>
#include <grasp_transfer/shipped_hands.hpp>
#include <topograsp/model/models/shadow_hand.hpp>

TOPOGRASP_HAND_PROGRAM("shadow", topograsp::models::shadow_hand)
