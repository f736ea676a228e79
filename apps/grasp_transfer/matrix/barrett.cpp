// SPDX-License-Identifier: BSD-3-Clause
// The transfer matrix: every transfer to the Barrett hand, from any source (pair.hpp).
#include "pair_body.hpp"

namespace matrix {
TOPOGRASP_MATRIX_TARGET(models::barrett_bh8);
}  // namespace matrix
