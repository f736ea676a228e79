// SPDX-License-Identifier: BSD-3-Clause
// The transfer matrix: human -> LEAP (pair.hpp).
#include "pair_body.hpp"

namespace matrix {
TOPOGRASP_MATRIX_PAIR(models::leap_hand, models::human_hand);
}  // namespace matrix
