// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The placing baselines: the target hand put where the source hand was, closed (autoclose, the
/// paper's; transplant, the grasp centres paired and the hand opened).
#pragma once

#include <algorithm>

#include <topograsp/grasp/transfer/common.hpp>

namespace topograsp {

/// The transplant baseline for any pair of hands: \p Target's grasp frame at the source's
/// (grasp_frame: the same point, its approach and "up" along the source's), its joints at
/// opened_preshape(options.transplant_opening, base_preshape), backed off along its approach only
/// as far as needed to clear the object, then closed until contact and judged (with \p second if
/// set). Unlike the other methods it is not moved on until contact when it is clear: a baseline is
/// not given a help that weakens it (docs/results.md measures it). Not planned (reason says why)
/// for a source that unusable_source refuses or a hand that cannot be placed clear of the object.
template <const auto& Target>
  requires HandModel<decltype(Target)>
[[nodiscard]] HandTransfer<Target> transplant_grasp(const GraspObject& object,
                                                    const SourceGrasp& source,
                                                    const TransferOptions& options = {},
                                                    const SecondJudge<Target>& second = {}) {
  detail::TransferRun<Target> run(TransferMethod::transplant, unusable_source(source), options);
  if (run.refused()) return run.unplanned();
  const Eigen::Isometry3d target = source.grasp_frame;
  const Vec<Target.nq> preshape =
      opened_preshape<Target>(options.transplant_opening, base_preshape<Target>(options));
  return run.place_and_judge(object, root_for_grasp_frame<Target>(target, preshape), preshape,
                             target.linear().col(2), 0.0, options.sim, second,
                             "the hand cannot be placed clear of the object");
}

/// The paper's baseline "autoclose" for any pair of hands: \p Target's palm frame at the
/// source's (palm_frame: the palm centres paired, the approach and "up" along the source's), its
/// joints at its usual pre-shape (base_preshape: options.sdh_preshape for the SDH), backed off
/// along its approach only as far as needed to clear the object (searched up to the farthest
/// fingertip's distance from the palm beyond options.sim.standoff), then closed until contact and
/// judged (with \p second if set). Not planned (reason says why) for a source that unusable_source
/// refuses or a hand that cannot be placed clear of the object.
template <const auto& Target>
  requires HandModel<decltype(Target)>
[[nodiscard]] HandTransfer<Target> autoclose_grasp(const GraspObject& object,
                                                   const SourceGrasp& source,
                                                   const TransferOptions& options = {},
                                                   const SecondJudge<Target>& second = {}) {
  detail::TransferRun<Target> run(TransferMethod::autoclose, unusable_source(source), options);
  if (run.refused()) return run.unplanned();
  const Eigen::Isometry3d target = source.palm_frame;
  const Vec<Target.nq> preshape = base_preshape<Target>(options);
  // A palm where the source's was can put the fingers their whole length into the object: the
  // search for a clear start backs off that much further than sim.standoff.
  KinematicsData<Target> d;
  forward_kinematics(d, preshape);
  const Vec3 palm = frame_pose(d, detail::palm_frame_of<Target>()).translation();
  double reach = 0.0;
  for (int f = 0; f < static_cast<int>(Target.fingers.size()); ++f)
    reach = std::max(reach, (world_point(d, finger_tip<Target>(f)) - palm).norm());
  GraspSimOptions sim = options.sim;
  sim.standoff += reach;
  return run.place_and_judge(object, root_for_palm_frame<Target>(target, preshape), preshape,
                             target.linear().col(2), 0.0, sim, second,
                             "the hand cannot be placed clear of the object");
}

}  // namespace topograsp
