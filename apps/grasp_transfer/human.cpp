// SPDX-License-Identifier: BSD-3-Clause
// The human hand's side of grasp_transfer (program.hpp), the same whatever hand the
// demonstrations go to: its demonstrations, their MuJoCo judge and their scenes, compiled once
// for every hand of the program rather than in each hand's translation unit (the programs' units
// define TOPOGRASP_EXTERN_HUMAN_DEMONSTRATIONS: apps/CMakeLists.txt, topograsp_add_hand_program).
#include <grasp_transfer/program.hpp>
#include <topograsp/grasp/human_side.hpp>

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
