// SPDX-License-Identifier: BSD-3-Clause
// The human hand's side of grasp_transfer (program.hpp), the same whatever hand the
// demonstrations go to: the MuJoCo judge and the scenes of its demonstrations, compiled once for
// every hand of the program rather than in each hand's translation unit (the demonstrations
// themselves: compiled/hand_independent.cpp).
#include <grasp_transfer/program.hpp>

namespace topograsp::app {

std::string human_scene(const GraspObject& object, const HumanGrasp& g,
                        const TransferOptions& options) {
  return grasp_mjcf<models::human_hand>(object, g.hand_pose, g.q, g.object_pose,
                                        g.closing.hold_torque, options);
}

#ifdef TOPOGRASP_HAVE_MUJOCO
StabilityResult mujoco_judge_human(const HandScene<models::human_hand>& scene,
                                   const StabilityOptions& options) {
  return stability_suite(MujocoScene(scene), options);
}
#endif

}  // namespace topograsp::app
