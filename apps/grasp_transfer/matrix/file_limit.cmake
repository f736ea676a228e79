# SPDX-License-Identifier: BSD-3-Clause
# cmake -DPROGRAM=transfer_matrix -DSOURCE=<a finished run's folder> -DDIR=<scratch folder>
#       -P file_limit.cmake
# A copy of a finished run's folder, then the same run into it under a file-size limit (2 KB:
# less than the results page, the first file written) that makes a write fail part way, as a full
# disk would: the run must fail with a message naming the write, and leave the previous run's files
# byte-identical (docs/testing.md, "What is refused (reliability, round two)").
file(REMOVE_RECURSE "${DIR}")
file(MAKE_DIRECTORY "${DIR}")
foreach(f matrix.json matrix.md index.html)
  file(COPY_FILE "${SOURCE}/${f}" "${DIR}/${f}")
endforeach()
# ulimit -f counts 512-byte blocks in a POSIX sh; SIGXFSZ is ignored by the program.
execute_process(COMMAND sh -c "ulimit -f 4 && exec \"$0\" \"$@\"" "${PROGRAM}" --objects bottle
                        --max-hypotheses 6 --methods fingertip,virtual_finger --quiet --out "${DIR}"
                RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
if(status EQUAL 0)
  message(FATAL_ERROR "expected the run to fail past the file-size limit; it succeeded")
endif()
if(NOT err MATCHES "cannot write")
  message(FATAL_ERROR "expected a message naming the failed write (exit ${status}): ${err}")
endif()
foreach(f matrix.json matrix.md index.html)
  file(SHA256 "${SOURCE}/${f}" before)
  file(SHA256 "${DIR}/${f}" after)
  if(NOT before STREQUAL after)
    message(FATAL_ERROR "${f} changed although the run failed")
  endif()
endforeach()
message(STATUS "failed as expected (${status}), the previous run intact: ${err}")
