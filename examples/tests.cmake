# SPDX-License-Identifier: BSD-3-Clause
# How each example runs as a test (short arguments so the suite stays fast).
add_test(NAME "example: fingertips" COMMAND fingertips)
add_test(NAME "example: custom_hand" COMMAND custom_hand)
add_test(NAME "example: wrap" COMMAND wrap --out ${CMAKE_CURRENT_BINARY_DIR}/wrap-out)
add_test(NAME "example: grasp_transfer (small run)"
         COMMAND grasp_transfer --max-hypotheses 4 --jobs 2 --quiet --figures
                 --out ${CMAKE_CURRENT_BINARY_DIR}/grasp_transfer_small)
add_test(NAME "example: render_grasp" COMMAND render_grasp --out ${CMAKE_CURRENT_BINARY_DIR}/render-out)
# Bad input: a clear message on stderr and a non-zero exit status.
foreach(case IN ITEMS "unknown object|--objects,anvil|unknown object \"anvil\""
                      "unknown method|--methods,teleport|unknown method \"teleport\""
                      "bad shard|--shard,4/3|--shard: expected 1 <= K <= N"
                      "bad jobs|--jobs,zero|--jobs: expected a number"
                      "unwritable out|--out,/proc/grasp_transfer|--out: cannot write"
                      "unknown parameter|--set,reach=1|unknown transfer parameter \"reach\""
                      "negative parameter|--set,final_approach=-1|value: final_approach must be"
                      "parameter without value|--set,final_approach|--set: expected NAME=VALUE"
                      "unknown winding reference|--winding-reference,palm|winding_reference: unknown reference")
  string(REPLACE "|" ";" parts "${case}")
  list(GET parts 0 name)
  list(GET parts 1 args)
  list(GET parts 2 expect)
  string(REPLACE "," ";" args "${args}")
  add_test(NAME "example: grasp_transfer rejects ${name}"
           COMMAND ${CMAKE_COMMAND} "-DCOMMAND=$<TARGET_FILE:grasp_transfer>;${args}"
                   "-DEXPECT=${expect}" -P ${CMAKE_CURRENT_SOURCE_DIR}/expect_failure.cmake)
endforeach()
