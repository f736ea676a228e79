// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The LEAP Hand (right; Shaw, Agarwal and Pathak, RSS 2023), 16 joints, four digits: MuJoCo
/// Menagerie's model imported with its hand description, data/hands/leap_hand.json (the
/// fingertips, palm centre, fingers and thumb, closing directions and the actuators' torque and
/// speed limits the file cannot give), by tools/import_shipped_hands.sh into
/// imported/leap_hand.hpp (docs/models.md, "Today's hands", for the sources of every number). Not
/// in topograsp.hpp: include it where it is used.
#pragma once

#include <topograsp/model/models/imported/leap_hand.hpp>

namespace topograsp::models {

/// The LEAP Hand, right: palm frame as in Menagerie's file, the fingers along +x, the palm
/// facing -z. Configuration: [if_mcp, if_rot, if_pip, if_dip, mf_..., rf_..., th_cmc, th_axl,
/// th_mcp, th_ipl] (rad); *_rot are the abductions. palm_centre: on the palm's face, z out of
/// the palm, y along the fingers. Its motors, Dynamixel XC330-M288-T, at the effort and velocity
/// of the LEAP Hand's own URDF (the motor's stall torque and no-load speed at 5 V); the LEAP Hand
/// API's default current limit lets them give about a fifth of it.
inline constexpr const auto& leap_hand = imported::leap_hand::model;

}  // namespace topograsp::models
