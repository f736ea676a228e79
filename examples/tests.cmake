# SPDX-License-Identifier: BSD-3-Clause
# How each example runs as a test (short arguments so the suite stays fast).
add_test(NAME "example: fingertips" COMMAND fingertips)
add_test(NAME "example: custom_hand" COMMAND custom_hand)
add_test(NAME "example: wrap" COMMAND wrap --out ${CMAKE_CURRENT_BINARY_DIR}/wrap-out)
add_test(NAME "example: grasp_transfer (small run)"
         COMMAND grasp_transfer --max-hypotheses 8 --jobs 2 --quiet
                 --out ${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_small)
add_test(NAME "example: render_grasp" COMMAND render_grasp --out ${CMAKE_CURRENT_BINARY_DIR}/render-out)
