// SPDX-License-Identifier: BSD-3-Clause
// The transfer matrix: human -> Barrett (pair.hpp).
#include "pair_body.hpp"

namespace matrix {
TOPOGRASP_MATRIX_PAIR(models::barrett_bh8, models::human_hand);
}  // namespace matrix
