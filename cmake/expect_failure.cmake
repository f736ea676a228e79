# SPDX-License-Identifier: BSD-3-Clause
# cmake -DCOMMAND="prog;args" -DEXPECT="regex" [-DSTATUS=n] [-DMKDIR=path] [-DMKFILE=path]
#       [-DCOPY_TO=folder] -P expect_failure.cmake
# Passes if the command exits non-zero (exactly STATUS if given) and its stderr matches EXPECT.
# MKDIR / MKFILE first create a folder / an empty file (with its parent folders), for the cases
# that need a prepared output folder. COPY_TO runs a copy of prog made in an emptied folder (for a
# program that looks for others beside it).
if(DEFINED MKDIR)
  file(MAKE_DIRECTORY "${MKDIR}")
endif()
if(DEFINED MKFILE)
  get_filename_component(parent "${MKFILE}" DIRECTORY)
  file(MAKE_DIRECTORY "${parent}")
  file(WRITE "${MKFILE}" "")
endif()
if(DEFINED COPY_TO)
  file(REMOVE_RECURSE "${COPY_TO}")
  file(MAKE_DIRECTORY "${COPY_TO}")
  list(GET COMMAND 0 program)
  file(COPY "${program}" DESTINATION "${COPY_TO}")
  get_filename_component(program "${program}" NAME)
  list(REMOVE_AT COMMAND 0)
  list(PREPEND COMMAND "${COPY_TO}/${program}")
endif()
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
if(status EQUAL 0)
  message(FATAL_ERROR "expected a failure, the command succeeded")
endif()
if(DEFINED STATUS AND NOT status EQUAL STATUS)
  message(FATAL_ERROR "expected exit status ${STATUS}, got ${status}: ${err}")
endif()
if(NOT err MATCHES "${EXPECT}")
  message(FATAL_ERROR "stderr does not match \"${EXPECT}\": ${err}")
endif()
message(STATUS "failed as expected (${status}): ${err}")
