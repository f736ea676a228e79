// SPDX-License-Identifier: BSD-3-Clause
// The definition of matrix::transfer_pair (pair.hpp), included only by the translation units that
// compile it for one target hand.
#pragma once

#include <utility>

#include "pair.hpp"
#ifdef TOPOGRASP_HAVE_MUJOCO
#include <topograsp/mujoco/mujoco_scene.hpp>
#endif

namespace matrix {

template <const auto& M>
SecondJudge<M> mujoco_judge() {
#ifdef TOPOGRASP_HAVE_MUJOCO
  return [](const HandScene<M>& scene, const StabilityOptions& o) {
    return stability_suite(MujocoScene(scene), o);
  };
#else
  return {};
#endif
}

template <const auto& M>
Record record(std::string pair, const std::string& object, const HandTransfer<M>& t) {
  Record r{std::move(pair),
           object,
           std::string(to_string(t.method)),
           t.planned,
           t.stable(),
           t.planned && t.second && t.second->stable,
           t.second.has_value(),
           {},
           std::numeric_limits<double>::quiet_NaN()};
  if (!t.planned)
    r.failure = "not planned: " + t.reason;
  else if (!t.stable())
    r.failure = "unstable: " + t.stability.reason.substr(0, t.stability.reason.find(':'));
  if (t.planned && t.source_winding)
    r.winding_error = (t.winding - *t.source_winding).cwiseAbs().maxCoeff();
  return r;
}

template <const auto& T>
std::vector<HandTransfer<T>> transfer_pair(const std::string& pair, const GraspObject& object,
                                           const SourceGrasp& source,
                                           const std::vector<TransferMethod>& methods,
                                           const TransferOptions& options,
                                           std::vector<Record>& out) {
  std::vector<HandTransfer<T>> ts;
  for (const TransferMethod m : methods) {
    ts.push_back(transfer_hand<T>(m, object, source, options, mujoco_judge<T>()));
    out.push_back(record(pair, object.name, ts.back()));
  }
  return ts;
}

}  // namespace matrix
