// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The Wonik Robotics Allegro Hand (right), 16 joints, four digits: MuJoCo Menagerie's model
/// imported with its hand description, data/hands/allegro_hand.json (the fingertips, palm centre,
/// fingers and thumb, closing directions and the actuators' torque and speed limits the file
/// cannot give), by tools/import_shipped_hands.sh into imported/wonik_allegro.hpp
/// (docs/models.md, "Today's hands", for the sources of every number). Not in topograsp.hpp:
/// include it where it is used.
#pragma once

#include <topograsp/model/models/imported/wonik_allegro.hpp>

namespace topograsp::models {

/// The Allegro Hand, right: palm frame as in Menagerie's file, fingers along +z, the palm facing
/// +x. Configuration: [ffj0..3, mfj0..3, rfj0..3, thj0..3] (rad), each digit's j0 its abduction
/// (thumb: its rotation into opposition). The thumb is the thumb; the index (ff), middle (mf)
/// and ring (rf) are its fingers. palm_centre: on the palm's face, z out of the palm, y along
/// the fingers.
inline constexpr const auto& allegro_hand = imported::wonik_allegro::model;

}  // namespace topograsp::models
