# SPDX-License-Identifier: BSD-3-Clause
# Helpers of the CMake scripts that run grasp_transfer in the tests (shard_merge.cmake,
# hands_merge.cmake): PROGRAM is the program, set by the script's caller.

# run_program(<what> <argument>...): runs PROGRAM with the arguments; a run that fails stops the
# script naming <what>, the exit status and what the program wrote to stderr. Sets run_output to
# what it wrote to stdout.
function(run_program what)
  execute_process(COMMAND "${PROGRAM}" ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out
                  ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}): ${err}")
  endif()
  set(run_output "${out}" PARENT_SCOPE)
endfunction()

# run_two_shards_merged(<dir> <first> <second> <argument>...): runs shards 1/2 and 2/2 of the run
# the arguments give into <dir>/shard1 and <dir>/shard2, then merges them, shard <first> named
# first, into <dir>/merged. Sets run_output to what the merge wrote to stdout.
function(run_two_shards_merged dir first second)
  foreach(k 1 2)
    run_program("shard ${k}/2" ${ARGN} --shard ${k}/2 --out "${dir}/shard${k}")
  endforeach()
  run_program("merge" merge --quiet --out "${dir}/merged" "${dir}/shard${first}"
              "${dir}/shard${second}")
  set(run_output "${run_output}" PARENT_SCOPE)
endfunction()
