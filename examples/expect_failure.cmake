# SPDX-License-Identifier: BSD-3-Clause
# cmake -DCOMMAND="prog;args" -DEXPECT="regex" -P expect_failure.cmake
# Passes if the command exits non-zero and its stderr matches EXPECT.
execute_process(COMMAND ${COMMAND} RESULT_VARIABLE status ERROR_VARIABLE err OUTPUT_QUIET)
if(status EQUAL 0)
  message(FATAL_ERROR "expected a failure, the command succeeded")
endif()
if(NOT err MATCHES "${EXPECT}")
  message(FATAL_ERROR "stderr does not match \"${EXPECT}\": ${err}")
endif()
message(STATUS "failed as expected: ${err}")
