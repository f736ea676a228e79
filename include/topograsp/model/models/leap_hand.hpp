// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The LEAP Hand (right; Shaw, Agarwal and Pathak, RSS 2023), 16 joints, four digits: its links,
/// joints and collision shapes imported from MuJoCo Menagerie's model (imported/leap_hand.hpp,
/// made by topograsp_import_hand), and the hand description the file cannot give: fingertips,
/// palm centre, fingers and thumb, closing directions and the actuators' torque limits
/// (docs/models.md, "Today's hands"). Not in topograsp.hpp: include it where it is used.
#pragma once

#include <topograsp/model/model.hpp>
#include <topograsp/model/models/imported/leap_hand.hpp>

namespace topograsp::models {

/// The LEAP Hand's actuators, Dynamixel XC330-M288-T (docs/models.md): the effort and velocity
/// of the LEAP Hand's own URDF (LEAP_Hand_Sim), the motor's stall torque and no-load speed at
/// 5 V. The LEAP Hand API's default current limit (350 mA) lets the motors give about a fifth
/// of it.
namespace leap_dynamics {
inline constexpr double torque = 0.95;  ///< N m
inline constexpr double speed = 8.48;   ///< rad/s
}  // namespace leap_dynamics

namespace detail {
/// The imported links with the actuators and closing directions of leap_hand.
inline constexpr auto leap_links = [] {
  using namespace leap_dynamics;
  auto l = imported::leap_hand::links;
  for (LinkSpec& s : l) {
    if (s.type == JointType::fixed) continue;
    // Every joint turns about its -z; the abductions (the *_px links, joints *_rot) neither
    // open nor close.
    const bool abduction = s.name.view().substr(2) == "_px" && s.name.view()[0] != 't';
    s = s.actuator(torque, speed).closes(abduction ? 0.0 : 1.0);
  }
  return l;
}();
}  // namespace detail

/// The LEAP Hand, right: palm frame as in Menagerie's file, the fingers along +x, the palm
/// facing -z. Configuration: [if_mcp, if_rot, if_pip, if_dip, mf_..., rf_..., th_cmc, th_axl,
/// th_mcp, th_ipl] (rad); *_rot are the abductions. palm_centre: on the palm's face, z out of
/// the palm, y along the fingers.
inline constexpr auto leap_hand = make_model(
    "leap_hand", detail::leap_links, imported::leap_hand::shapes,
    frames(
        frame("if_tip", "if_ds", at(-0.0008, -0.05, 0.0145)),
        frame("mf_tip", "mf_ds", at(-0.0008, -0.05, 0.0145)),
        frame("rf_tip", "rf_ds", at(-0.0008, -0.05, 0.0145)),
        frame("th_tip", "th_ds", at(-0.0008, -0.0621, -0.0145)),
        frame("palm_centre", "palm", Pose{{0, 1, 0, 1, 0, 0, 0, 0, -1}, {-0.04, -0.022, -0.0346}})),
    hand("palm_centre", finger("index", {"if_bs", "if_px", "if_md", "if_ds", "if_tip"}),
         finger("middle", {"mf_bs", "mf_px", "mf_md", "mf_ds", "mf_tip"}),
         finger("ring", {"rf_bs", "rf_px", "rf_md", "rf_ds", "rf_tip"}),
         thumb("thumb", {"th_mp", "th_bs", "th_px", "th_ds", "th_tip"})));

}  // namespace topograsp::models
