// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The Shadow Dexterous Hand E3M5 (right), from its palm: 22 joints, five digits: MuJoCo
/// Menagerie's model imported from the palm (--root rh_palm: the wrist and forearm left out, as
/// the SDH and the Barrett hand have none) with its hand description, data/hands/shadow_hand.json
/// (the fingertips, palm centre, fingers and thumb, closing directions and the actuators' torque
/// and speed limits, Shadow's own, in place of the file's), by tools/import_shipped_hands.sh into
/// imported/shadow_hand.hpp (docs/models.md, "Today's hands", for the sources of every number).
/// Not in topograsp.hpp: include it where it is used.
#pragma once

#include <topograsp/model/models/imported/shadow_hand.hpp>

namespace topograsp::models {

/// The Shadow Hand, right, from its palm: palm frame as in Menagerie's file, the fingers along
/// +z, the palm facing -y. Configuration: [FFJ4..1, MFJ4..1, RFJ4..1, LFJ5..1, THJ5..1] (rad),
/// J4 the abductions. THJ4 (into the palm), THJ2 and THJ1 (flexions, their axes parallel at rest)
/// close; THJ5 turns the thumb about the palm, THJ3 (+-12 degrees) tilts it within THJ4's plane.
/// palm_centre: on the palm's face, z out of the palm, y along the fingers.
inline constexpr const auto& shadow_hand = imported::shadow_hand::model;

}  // namespace topograsp::models
