// SPDX-License-Identifier: BSD-3-Clause
// The transfer matrix: human -> Allegro and SDH -> Allegro (pair.hpp).
#include "pair_body.hpp"

namespace matrix {
TOPOGRASP_MATRIX_PAIR(models::allegro_hand, models::human_hand);
TOPOGRASP_MATRIX_PAIR(models::allegro_hand, models::schunk_sdh);
}  // namespace matrix
