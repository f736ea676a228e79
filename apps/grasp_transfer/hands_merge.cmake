# SPDX-License-Identifier: BSD-3-Clause
# cmake -DPROGRAM=grasp_transfer -DDIR=folder -P hands_merge.cmake
# grasp_transfer --hands sdh,barrett: a small run whole, then as shards 1/2 and 2/2 merged; the
# merged folder has every hand's results.json and the same table of every hand (hands.md) as the
# whole run. Then --resume of the whole run runs no hand again.
include(${CMAKE_CURRENT_LIST_DIR}/run_program.cmake)
file(REMOVE_RECURSE "${DIR}")
set(run --hands sdh,barrett --judge builtin --max-hypotheses 4 --objects bottle
        --methods topological,transplant --jobs 2 --quiet)
run_program("the whole run" ${run} --out "${DIR}/whole")
run_two_shards_merged("${DIR}" 1 2 ${run})
set(out "${run_output}")
foreach(hand sdh barrett)
  if(NOT EXISTS "${DIR}/merged/${hand}/results.json")
    message(FATAL_ERROR "the merge wrote no ${hand}/results.json: ${out}")
  endif()
endforeach()
file(READ "${DIR}/whole/hands.md" whole)
file(READ "${DIR}/merged/hands.md" merged)
if(NOT whole STREQUAL merged OR NOT whole MATCHES "barrett \\(barrett_bh8\\)")
  message(FATAL_ERROR "the merged table differs from the whole run's:\n${merged}\n${whole}")
endif()
execute_process(COMMAND "${PROGRAM}" ${run} --resume --out "${DIR}/whole" RESULT_VARIABLE status
                OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0 OR NOT out MATCHES "sdh: finished in [^\n]*, not run again"
   OR NOT out MATCHES "barrett: finished in [^\n]*, not run again")
  message(FATAL_ERROR "--resume of a finished --hands run (${status}): ${out} ${err}")
endif()
message(STATUS "the merged shards give the whole run's table of every hand")
