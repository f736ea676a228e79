# SPDX-License-Identifier: BSD-3-Clause
# cmake -DPROGRAM=grasp_transfer -DSOURCE=<a finished run's folder> -DDIR=<scratch folder>
#       -P file_limit.cmake
# A copy of a finished run's folder, then a run into it under a file-size limit (2 KB: less than
# the first scene written) that makes a write fail part way, as a full disk would: the run must
# fail with a message naming the write, and leave the previous run's files byte-identical, with no
# file added beside them (the failed run's staging folder, which keeps its journal for --resume,
# aside; docs/testing.md, "What is refused (reliability, round two)").
# The SHA-256 of every file under DIR but the staging folders (names starting with "."), as
# "path=sum", sorted by path.
function(hash_files out)
  file(GLOB_RECURSE files LIST_DIRECTORIES false RELATIVE "${DIR}" "${DIR}/*")
  list(FILTER files EXCLUDE REGEX "^[.]")
  list(SORT files)
  set(sums)
  foreach(f IN LISTS files)
    file(SHA256 "${DIR}/${f}" sum)
    list(APPEND sums "${f}=${sum}")
  endforeach()
  set(${out} "${sums}" PARENT_SCOPE)
endfunction()
file(REMOVE_RECURSE "${DIR}")
file(COPY "${SOURCE}/" DESTINATION "${DIR}")
hash_files(before_sums)
# ulimit -f counts 512-byte blocks in a POSIX sh; SIGXFSZ is ignored by the program.
execute_process(COMMAND sh -c "ulimit -f 4 && exec \"$0\" \"$@\"" "${PROGRAM}" --objects bottle
                        --max-hypotheses 1 --methods transplant --judge builtin --quiet
                        --out "${DIR}"
                RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
if(status EQUAL 0)
  message(FATAL_ERROR "expected the run to fail past the file-size limit; it succeeded")
endif()
if(NOT err MATCHES "cannot write")
  message(FATAL_ERROR "expected a message naming the failed write (exit ${status}): ${err}")
endif()
hash_files(after_sums)
if(NOT before_sums STREQUAL after_sums)
  message(FATAL_ERROR "the previous run's files changed although the run failed:\n"
                      "before: ${before_sums}\nafter: ${after_sums}")
endif()
list(LENGTH before_sums count)
message(STATUS "failed as expected (${status}), the previous run's ${count} files intact: ${err}")
