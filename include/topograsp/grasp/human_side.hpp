// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The human hand's side compiled once: demonstrate() and demonstrate_recorded() are templates,
/// compiled in every translation unit that calls them (about 20 s of g++ -O3 CPU each). A program
/// of several such units defines TOPOGRASP_EXTERN_HUMAN_DEMONSTRATIONS in all of them (the
/// headers then declare the two compiled elsewhere) and includes this header in exactly one,
/// which compiles them (docs/benchmarks.md, "The human hand's side, compiled once").
#pragma once

#include <topograsp/grasp/human_grasps.hpp>
#include <topograsp/grasp/keypoint_fit.hpp>

namespace topograsp {

template HumanGrasp demonstrate<void>(const GraspObject&, const GraspHypothesis&, int,
                                      const GraspSimOptions&);
template HumanGrasp demonstrate_recorded<void>(const GraspObject&, const KeypointGrasp&, int,
                                               const GraspSimOptions&, KeypointFit*);

}  // namespace topograsp
