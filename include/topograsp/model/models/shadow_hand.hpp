// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The Shadow Dexterous Hand E3M5 (right), from its palm: 22 joints, five digits, its links,
/// joints and collision shapes imported from MuJoCo Menagerie's model (imported/shadow_hand.hpp,
/// made by topograsp_import_hand --root rh_palm: the wrist and forearm left out, as the SDH and the
/// Barrett hand have none), and the hand description the file cannot give: fingertips, palm
/// centre, fingers and thumb, closing directions and the actuators' torque limits
/// (docs/models.md, "Today's hands"). Not in topograsp.hpp: include it where it is used.
#pragma once

#include <topograsp/model/model.hpp>
#include <topograsp/model/models/imported/shadow_hand.hpp>

namespace topograsp::models {

/// The Shadow Hand's actuators (docs/models.md): the efforts and velocities of Shadow's own
/// description (shadow-robot/sr_common, sr_description xacros), N m and rad/s. Menagerie's
/// model limits most joints to 1 N m (the imported file's values, replaced here).
namespace shadow_dynamics {
inline constexpr double finger_torque = 2.0;  ///< J1-J4 of the fingers, LFJ5
inline constexpr double finger_speed = 2.0;
inline constexpr double thj5_torque = 5.0, thj4_torque = 3.0, thj3_torque = 2.0, thj2_torque = 2.0,
                        thj1_torque = 1.0;
inline constexpr double thumb_speed = 4.0;  ///< THJ5, THJ4, THJ3, THJ1
}  // namespace shadow_dynamics

namespace detail {
/// The imported links with the actuators and closing directions of shadow_hand.
inline constexpr auto shadow_links = [] {
  using namespace shadow_dynamics;
  auto l = imported::shadow_hand::links;
  for (LinkSpec& s : l) {
    if (s.type == JointType::fixed) continue;
    const std::string_view part = s.name.view().substr(5);  // after "rh_ff" and the like
    const bool thumb = s.name.view().substr(3, 2) == "th";
    if (thumb) {
      const double torque = part == "base"       ? thj5_torque
                            : part == "proximal" ? thj4_torque
                            : part == "hub"      ? thj3_torque
                            : part == "middle"   ? thj2_torque
                                                 : thj1_torque;
      s = s.actuator(torque, part == "middle" ? finger_speed : thumb_speed, s.armature);
      // THJ4 (into the palm), THJ2 and THJ1 (flexions, their axes parallel at rest) close; THJ5
      // turns the thumb about the palm, THJ3 (+-12 degrees) tilts it within THJ4's plane.
      s = s.closes(part == "proximal" || part == "middle" || part == "distal" ? 1.0 : 0.0);
    } else {
      s = s.actuator(finger_torque, finger_speed, s.armature).closes(part == "knuckle" ? 0.0 : 1.0);
    }
  }
  return l;
}();
}  // namespace detail

/// The Shadow Hand, right, from its palm: palm frame as in Menagerie's file, the fingers along
/// +z, the palm facing -y. Configuration: [FFJ4..1, MFJ4..1, RFJ4..1, LFJ5..1, THJ5..1] (rad),
/// J4 the abductions. palm_centre: on the palm's face, z out of the palm, y along the fingers.
inline constexpr auto shadow_hand = make_model(
    "shadow_hand", detail::shadow_links, imported::shadow_hand::shapes,
    join(imported::shadow_hand::frames,
         frames(frame("ff_tip", "rh_ffdistal", at(0, 0, 0.032)),
                frame("mf_tip", "rh_mfdistal", at(0, 0, 0.032)),
                frame("rf_tip", "rh_rfdistal", at(0, 0, 0.032)),
                frame("lf_tip", "rh_lfdistal", at(0, 0, 0.032)),
                frame("th_tip", "rh_thdistal", at(0, 0, 0.035)),
                frame("palm_centre", "rh_palm",
                      Pose{{1, 0, 0, 0, 0, -1, 0, 1, 0}, {0.0, -0.0223, 0.045}}))),
    hand(
        "palm_centre",
        finger("index", {"rh_ffknuckle", "rh_ffproximal", "rh_ffmiddle", "rh_ffdistal", "ff_tip"}),
        finger("middle", {"rh_mfknuckle", "rh_mfproximal", "rh_mfmiddle", "rh_mfdistal", "mf_tip"}),
        finger("ring", {"rh_rfknuckle", "rh_rfproximal", "rh_rfmiddle", "rh_rfdistal", "rf_tip"}),
        finger("little", {"rh_lfmetacarpal", "rh_lfknuckle", "rh_lfproximal", "rh_lfmiddle",
                          "rh_lfdistal", "lf_tip"}),
        thumb("thumb",
              {"rh_thbase", "rh_thproximal", "rh_thhub", "rh_thmiddle", "rh_thdistal", "th_tip"})));

}  // namespace topograsp::models
