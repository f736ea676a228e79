# SPDX-License-Identifier: BSD-3-Clause
# cmake -DPROGRAM=grasp_transfer -DDIR=folder -P run_locally.cmake
# Runs the Slurm job scripts of this folder without Slurm, as the scheduler would: shard.sbatch
# once per array task (SLURM_ARRAY_TASK_ID 1 and 2 of 2, the second twice, as after a requeue),
# then merge.sbatch; checks that the merged folder has the results of both shards.
file(REMOVE_RECURSE "${DIR}")
set(ENV{PROGRAM} "${PROGRAM}")
set(ENV{OUT} "${DIR}")
set(ENV{SHARDS} 2)
set(ENV{ARGS} "--judge builtin --max-hypotheses 4 --objects bottle")
get_filename_component(here "${CMAKE_CURRENT_LIST_FILE}" DIRECTORY)
foreach(task 1 2 2)
  set(ENV{SLURM_ARRAY_TASK_ID} ${task})
  execute_process(COMMAND bash "${here}/shard.sbatch" RESULT_VARIABLE status ERROR_VARIABLE err
                  OUTPUT_QUIET)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "shard.sbatch, task ${task}: status ${status}: ${err}")
  endif()
endforeach()
execute_process(COMMAND bash "${here}/merge.sbatch" RESULT_VARIABLE status ERROR_VARIABLE err
                OUTPUT_VARIABLE out)
if(NOT status EQUAL 0 OR NOT EXISTS "${DIR}/merged/results.json")
  message(FATAL_ERROR "merge.sbatch: status ${status}: ${err}")
endif()
file(READ "${DIR}/merged/results.json" doc)
string(JSON hypotheses GET "${doc}" objects 0 hypotheses)
if(NOT hypotheses EQUAL 4)
  message(FATAL_ERROR "the merged run has ${hypotheses} hypotheses, expected 4")
endif()
unset(ENV{SLURM_ARRAY_TASK_ID})
execute_process(COMMAND bash "${here}/shard.sbatch" RESULT_VARIABLE status ERROR_VARIABLE err)
if(status EQUAL 0 OR NOT err MATCHES "submit as a job array")
  message(FATAL_ERROR "shard.sbatch outside an array: status ${status}: ${err}")
endif()
message(STATUS "the job scripts ran 2 shards and merged them")
