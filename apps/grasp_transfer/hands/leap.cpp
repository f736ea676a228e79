// SPDX-License-Identifier: BSD-3-Clause
// grasp_transfer --hand leap: the demonstrations transferred to topograsp::models::leap_hand
// (program.hpp).
#include <grasp_transfer/program.hpp>
#include <grasp_transfer/shipped_hands.hpp>
#include <topograsp/model/models/leap_hand.hpp>

TOPOGRASP_HAND_PROGRAM("leap", topograsp::models::leap_hand)
