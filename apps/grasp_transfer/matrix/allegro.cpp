// SPDX-License-Identifier: BSD-3-Clause
// The transfer matrix: every transfer to the Allegro hand, from any source (pair.hpp).
#include "pair_body.hpp"

namespace matrix {
TOPOGRASP_MATRIX_TARGET(models::allegro_hand);
}  // namespace matrix
