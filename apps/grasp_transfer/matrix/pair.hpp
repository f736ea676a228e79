// SPDX-License-Identifier: BSD-3-Clause
// The transfer matrix's one step: a source grasp transferred to one target hand by each method,
// each result judged and kept as a Record. transfer_pair is instantiated for each target hand in
// a file of its own (sdh.cpp, barrett.cpp, allegro.cpp, leap.cpp, shadow.cpp); main.cpp only
// declares it. The build compiles the six files as one translation unit (apps/CMakeLists.txt), and
// the hands' transfer steps once for every program (shipped_hands.hpp).
#pragma once

#include <limits>
#include <string>
#include <vector>

#include <grasp_transfer/shipped_hands.hpp>
#include <topograsp/grasp/transfer/hand.hpp>
#include <topograsp/model/models/allegro_hand.hpp>
#include <topograsp/model/models/leap_hand.hpp>
#include <topograsp/model/models/shadow_hand.hpp>

namespace matrix {

using namespace topograsp;

// One transfer's verdicts (pair, object, method, result).
struct Record {
  std::string pair, object, method;
  bool planned = false, stable = false, stable_second = false, second = false;
  std::string failure;  // empty if stable: "not planned: <reason>" or the first failed test
  double winding_error = std::numeric_limits<double>::quiet_NaN();
};

// \p source (a grasp of any hand) on \p object transferred to hand T on a free base by each of
// \p methods in turn (transfer_hand), judged by MuJoCo too where it is linked; one Record per
// transfer appended to \p out under the name \p pair. Returns the transfers, in the order of
// \p methods. One instantiation per target hand, whatever the source (SourceGrasp).
template <const auto& T>
std::vector<HandTransfer<T>> transfer_pair(const std::string& pair, const GraspObject& object,
                                           const SourceGrasp& source,
                                           const std::vector<TransferMethod>& methods,
                                           const TransferOptions& options,
                                           std::vector<Record>& out);

#define TOPOGRASP_MATRIX_TARGET(T)                                \
  template std::vector<HandTransfer<T>> transfer_pair<T>(         \
      const std::string&, const GraspObject&, const SourceGrasp&, \
      const std::vector<TransferMethod>&, const TransferOptions&, std::vector<Record>&)

extern TOPOGRASP_MATRIX_TARGET(models::schunk_sdh);
extern TOPOGRASP_MATRIX_TARGET(models::barrett_bh8);
extern TOPOGRASP_MATRIX_TARGET(models::allegro_hand);
extern TOPOGRASP_MATRIX_TARGET(models::leap_hand);
extern TOPOGRASP_MATRIX_TARGET(models::shadow_hand);

}  // namespace matrix
