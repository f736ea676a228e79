// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The shipped models and their compositions: the SDH on the 7-DOF arm (the paper's 14-DOF
/// robot), and the hands on a free 6-DOF base.
#pragma once

#include <topograsp/model/compose.hpp>
#include <topograsp/model/models/barrett_bh8.hpp>
#include <topograsp/model/models/human_hand.hpp>
#include <topograsp/model/models/schunk_arm.hpp>
#include <topograsp/model/models/schunk_sdh.hpp>

namespace topograsp::models {

/// The SDH on the Schunk arm's flange: 14 DOF, [arm_1..arm_7, knuckle, finger_12, finger_13,
/// finger_22, finger_23, thumb_2, thumb_3], as in the paper.
inline constexpr auto schunk_arm_sdh =
    attach(schunk_arm, "flange", schunk_sdh, {}, "schunk_arm_sdh");

/// The SDH on a free 6-DOF base (13 DOF: base x, y, z, rz, ry, rx, then the hand's 7).
inline constexpr auto schunk_sdh_free = on_free_base(schunk_sdh);

/// The human hand on a free 6-DOF base (26 DOF: base then the hand's 20).
inline constexpr auto human_hand_free = on_free_base(human_hand);

/// The Barrett hand on a free 6-DOF base (10 DOF).
inline constexpr auto barrett_bh8_free = on_free_base(barrett_bh8);

}  // namespace topograsp::models
