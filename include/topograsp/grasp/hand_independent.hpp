// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The grasp pipeline's templates that do not depend on the hand, compiled once: demonstrate() and
/// demonstrate_recorded() (the human hand's side), arm_reach(), affine_dimension(), with qhull
/// ferrari_canny_epsilon(), with MuJoCo the stability suite run in MuJoCo
/// (stability_suite<MujocoScene>). A template is compiled in every translation unit that calls it
/// (every unit that judges a grasp calls the last four). A program of several such units defines
/// TOPOGRASP_EXTERN_HAND_INDEPENDENT in all of them (the headers then declare these compiled
/// elsewhere) and includes this header in exactly one, which compiles them, with the same
/// definitions (TOPOGRASP_HAVE_QHULL, TOPOGRASP_HAVE_MUJOCO) as the rest. grasp/compiled_hand.hpp
/// does the same for what a transfer compiles per target hand (docs/benchmarks.md, "Compiling the
/// transfer once per program").
#pragma once

#include <topograsp/evaluation/grasp_wrench.hpp>
#include <topograsp/grasp/arm_reach.hpp>
#include <topograsp/grasp/human_grasps.hpp>
#include <topograsp/grasp/keypoint_fit.hpp>
#ifdef TOPOGRASP_HAVE_QHULL
#include <topograsp/evaluation/grasp_quality.hpp>
#endif
#ifdef TOPOGRASP_HAVE_MUJOCO
#include <topograsp/mujoco/mujoco_scene.hpp>
#endif

namespace topograsp {

template HumanGrasp demonstrate<void>(const GraspObject&, const GraspHypothesis&, int,
                                      const GraspSimOptions&);
template HumanGrasp demonstrate_recorded<void>(const GraspObject&, const KeypointGrasp&, int,
                                               const GraspSimOptions&, KeypointFit*);
template ArmReach arm_reach<void>(const GraspObject&, const Eigen::Isometry3d&,
                                  const Eigen::Isometry3d&, const Vec<7>&, const ArmReachOptions&);
template int affine_dimension<void>(const Eigen::Matrix<double, 6, Eigen::Dynamic>&, double);
#ifdef TOPOGRASP_HAVE_QHULL
template GraspQuality ferrari_canny_epsilon<void>(const Eigen::Matrix<double, 6, Eigen::Dynamic>&);
template GraspQuality ferrari_canny_epsilon<void>(std::span<const ContactForQuality>, const Vec3&,
                                                  double, const QualityOptions&);
#endif
#ifdef TOPOGRASP_HAVE_MUJOCO
template StabilityResult stability_suite<MujocoScene>(const MujocoScene&, const StabilityOptions&);
#endif

}  // namespace topograsp
