// SPDX-License-Identifier: BSD-3-Clause
// grasp_transfer --hand sdh: the demonstrations transferred to topograsp::models::schunk_sdh
// (program.hpp).
#include <grasp_transfer/program.hpp>
#include <grasp_transfer/shipped_hands.hpp>
#include <topograsp/model/models/schunk_sdh.hpp>

TOPOGRASP_HAND_PROGRAM("sdh", topograsp::models::schunk_sdh)
