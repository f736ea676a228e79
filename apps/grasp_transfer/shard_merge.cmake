# SPDX-License-Identifier: BSD-3-Clause
# cmake -DPROGRAM=grasp_transfer -DDIR=folder -P shard_merge.cmake
# Runs shards 1/2 and 2/2 of a small run, merges them, and checks that the merged folder has a
# results.json and every scene the shards wrote; then that a merge with a shard missing fails
# with exit status 2, naming it.
include(${CMAKE_CURRENT_LIST_DIR}/run_program.cmake)
file(REMOVE_RECURSE "${DIR}")
set(run --judge builtin --max-hypotheses 6 --objects bottle --quiet)
run_two_shards_merged("${DIR}" 2 1 ${run})
set(out "${run_output}")
if(NOT out MATCHES "2 shard\\(s\\) merged" OR NOT EXISTS "${DIR}/merged/results.json")
  message(FATAL_ERROR "merge printed no summary or wrote no results.json: ${out}")
endif()
file(GLOB shard_scenes "${DIR}/shard1/scenes/*.xml" "${DIR}/shard2/scenes/*.xml")
file(GLOB merged_scenes "${DIR}/merged/scenes/*.xml")
list(LENGTH shard_scenes n_shards)
list(LENGTH merged_scenes n_merged)
if(n_shards EQUAL 0 OR NOT n_shards EQUAL n_merged)
  message(FATAL_ERROR "the shards wrote ${n_shards} scenes, the merge has ${n_merged}")
endif()
file(READ "${DIR}/merged/results.json" doc)
string(JSON shard GET "${doc}" config shard)
string(JSON hypotheses GET "${doc}" objects 0 hypotheses)
if(NOT shard STREQUAL "1/1" OR NOT hypotheses EQUAL 6)
  message(FATAL_ERROR "merged config shard ${shard}, hypotheses ${hypotheses}")
endif()
execute_process(COMMAND "${PROGRAM}" merge --out "${DIR}/partial" "${DIR}/shard1"
                RESULT_VARIABLE status OUTPUT_QUIET ERROR_VARIABLE err)
if(NOT status EQUAL 2 OR NOT err MATCHES "shard 2/2 is missing")
  message(FATAL_ERROR "a merge with a shard missing: status ${status}: ${err}")
endif()
message(STATUS "merged ${n_merged} scenes of 2 shards")
