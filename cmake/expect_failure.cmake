# SPDX-License-Identifier: BSD-3-Clause
# cmake -DCOMMAND="prog;args" -DEXPECT="regex" [-DSTATUS=n] [-DMKDIR=path] [-DMKFILE=path]
#       -P expect_failure.cmake
# Passes if the command exits non-zero (exactly STATUS if given) and its stderr matches EXPECT.
# MKDIR / MKFILE first create a folder / an empty file (with its parent folders), for the cases
# that need a prepared output folder.
if(DEFINED MKDIR)
  file(MAKE_DIRECTORY "${MKDIR}")
endif()
if(DEFINED MKFILE)
  get_filename_component(parent "${MKFILE}" DIRECTORY)
  file(MAKE_DIRECTORY "${parent}")
  file(WRITE "${MKFILE}" "")
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
