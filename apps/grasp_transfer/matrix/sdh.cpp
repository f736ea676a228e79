// SPDX-License-Identifier: BSD-3-Clause
// The transfer matrix: human -> SDH (pair.hpp).
#include "pair_body.hpp"

namespace matrix {
TOPOGRASP_MATRIX_PAIR(models::schunk_sdh, models::human_hand);
}  // namespace matrix
