// SPDX-License-Identifier: BSD-3-Clause
// The transfer matrix: every transfer to the LEAP hand, from any source (pair.hpp).
#include "pair_body.hpp"

namespace matrix {
TOPOGRASP_MATRIX_TARGET(models::leap_hand);
}  // namespace matrix
