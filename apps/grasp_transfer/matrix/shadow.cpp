// SPDX-License-Identifier: BSD-3-Clause
// The transfer matrix: human -> Shadow and Allegro -> Shadow (pair.hpp).
#include "pair_body.hpp"

namespace matrix {
TOPOGRASP_MATRIX_PAIR(models::shadow_hand, models::human_hand);
TOPOGRASP_MATRIX_PAIR(models::shadow_hand, models::allegro_hand);
}  // namespace matrix
