// SPDX-License-Identifier: BSD-3-Clause
/// \file
/// The transplant baseline: the target hand put where the source hand was, opened, closed.
#pragma once

#include <topograsp/grasp/transfer/common.hpp>

namespace topograsp {

/// The transplant baseline for any pair of hands: \p Target's grasp frame at the source's
/// (grasp_frame: the same point, its approach and "up" along the source's), its joints at
/// opened_preshape(options.transplant_opening, base_preshape), backed off along its approach only
/// as far as needed to clear the object, then closed until contact and judged (with \p second if
/// set). Unlike the other methods it is not moved on until contact when it is clear: a baseline is
/// not given a help that weakens it (docs/results.md measures it). Not planned (reason says why)
/// for a source that is not finite or a hand that cannot be placed clear of the object.
template <const auto& Target, const auto& Source>
  requires HandModel<decltype(Target)> && HandModel<decltype(Source)>
[[nodiscard]] HandTransfer<Target> transplant_grasp(const GraspObject& object,
                                                    const HandGrasp<Source>& source,
                                                    const TransferOptions& options = {},
                                                    const SecondJudge<Target>& second = {}) {
  detail::TransferRun<Target> run(TransferMethod::transplant,
                                  detail::unusable_source_grasp(source));
  if (run.refused()) return run.unplanned();
  const Eigen::Isometry3d target = grasp_frame(source);
  const Vec<Target.nq> preshape =
      opened_preshape<Target>(options.transplant_opening, base_preshape<Target>(options));
  return run.place_and_judge(object, root_for_grasp_frame<Target>(target, preshape), preshape,
                             target.linear().col(2), 0.0, options.sim, second,
                             "the hand cannot be placed clear of the object");
}

}  // namespace topograsp
