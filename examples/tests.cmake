# SPDX-License-Identifier: BSD-3-Clause
# How each example runs as a test (short arguments so the suite stays fast).
add_test(NAME "example: fingertips" COMMAND fingertips)
add_test(NAME "example: custom_hand" COMMAND custom_hand)
add_test(NAME "example: import_hand" COMMAND import_hand)
add_test(NAME "example: wrap" COMMAND wrap --out ${CMAKE_CURRENT_BINARY_DIR}/wrap-out)
add_test(NAME "example: render_grasp" COMMAND render_grasp --out ${CMAKE_CURRENT_BINARY_DIR}/render-out)
set_tests_properties("example: render_grasp" PROPERTIES LABELS end_to_end)
# The imported gripper's own grasp_transfer (topograsp_add_hand_program): a small run.
add_test(NAME "example: gripper_transfer (small run)"
         COMMAND gripper_transfer --objects bottle --max-hypotheses 2
                 --methods topological,transplant --jobs 2 --quiet --figures
                 --out ${CMAKE_CURRENT_BINARY_DIR}/gripper_transfer_out)
set_tests_properties("example: gripper_transfer (small run)" PROPERTIES
                     LABELS end_to_end PASS_REGULAR_EXPRESSION "results in .*gripper_transfer_out")
