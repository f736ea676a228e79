// SPDX-License-Identifier: BSD-3-Clause
// grasp_transfer --hand allegro: the demonstrations transferred to topograsp::models::allegro_hand
// (program.hpp).
#include <grasp_transfer/program.hpp>
#include <grasp_transfer/shipped_hands.hpp>
#include <topograsp/model/models/allegro_hand.hpp>

TOPOGRASP_HAND_PROGRAM("allegro", topograsp::models::allegro_hand)
