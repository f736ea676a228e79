// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The Wonik Robotics Allegro Hand (right), 16 joints, four digits: its links, joints and
/// collision shapes imported from MuJoCo Menagerie's model (imported/wonik_allegro.hpp, made by
/// topograsp_import_hand), and the hand description the file cannot give: fingertips, palm centre,
/// fingers and thumb, closing directions and the actuators' torque limits (docs/models.md,
/// "Today's hands"). Not in topograsp.hpp: include it where it is used.
#pragma once

#include <topograsp/model/model.hpp>
#include <topograsp/model/models/imported/wonik_allegro.hpp>

namespace topograsp::models {

/// The Allegro Hand's actuators (docs/models.md): the largest torque Wonik's v4 driver commands
/// per joint (its PWM limit over its torque-to-PWM constant, allegro_hand_ros_v4,
/// AllegroHandDrv.cpp), N m; the speed limit of Wonik's v4 URDF, rad/s.
namespace allegro_dynamics {
inline constexpr double roll_torque = 0.31;        ///< fingers' j0 (abduction)
inline constexpr double near_torque = 0.56;        ///< fingers' j1
inline constexpr double middle_torque = 0.375;     ///< fingers' j2
inline constexpr double far_torque = 0.24;         ///< fingers' j3
inline constexpr double thumb_roll_torque = 0.44;  ///< thj0
inline constexpr double thumb_near_torque = 0.34;  ///< thj1
inline constexpr double thumb_far_torque = 0.225;  ///< thj2, thj3
inline constexpr double speed = 7.0;
}  // namespace allegro_dynamics

namespace detail {
/// The imported links with the actuators and closing directions of allegro_hand.
inline constexpr auto allegro_links = [] {
  using namespace allegro_dynamics;
  auto l = imported::wonik_allegro::links;
  for (LinkSpec& s : l) {
    if (s.type == JointType::fixed) continue;
    const std::string_view n = s.name.view();
    const bool thumb = n.substr(0, 2) == "th";
    const std::string_view part = n.substr(3);
    const double torque = thumb ? (part == "base"       ? thumb_roll_torque
                                   : part == "proximal" ? thumb_near_torque
                                                        : thumb_far_torque)
                                : (part == "base"       ? roll_torque
                                   : part == "proximal" ? near_torque
                                   : part == "medial"   ? middle_torque
                                                        : far_torque);
    s = s.actuator(torque, speed).closes(thumb || part != "base" ? 1.0 : 0.0);
  }
  return l;
}();
}  // namespace detail

/// The Allegro Hand, right: palm frame as in Menagerie's file, fingers along +z, the palm facing
/// +x. Configuration: [ffj0..3, mfj0..3, rfj0..3, thj0..3] (rad), each digit's j0 its abduction
/// (thumb: its rotation into opposition). The thumb is the thumb; the index (ff), middle (mf)
/// and ring (rf) are its fingers. palm_centre: on the palm's face, z out of the palm, y along
/// the fingers.
inline constexpr auto allegro_hand = make_model(
    "allegro_hand", detail::allegro_links, imported::wonik_allegro::shapes,
    frames(frame("ff_tip_point", "ff_tip", at(0, 0, 0.041)),
           frame("mf_tip_point", "mf_tip", at(0, 0, 0.041)),
           frame("rf_tip_point", "rf_tip", at(0, 0, 0.041)),
           frame("th_tip_point", "th_tip", at(0, 0, 0.055)),
           frame("palm_centre", "palm", Pose{{0, 0, 1, 1, 0, 0, 0, 1, 0}, {0.0111, 0, -0.0475}})),
    hand("palm_centre",
         finger("index", {"ff_base", "ff_proximal", "ff_medial", "ff_distal", "ff_tip_point"}),
         finger("middle", {"mf_base", "mf_proximal", "mf_medial", "mf_distal", "mf_tip_point"}),
         finger("ring", {"rf_base", "rf_proximal", "rf_medial", "rf_distal", "rf_tip_point"}),
         thumb("thumb", {"th_base", "th_proximal", "th_medial", "th_distal", "th_tip_point"})));

}  // namespace topograsp::models
