# Runs a command and checks how it ends, for the CLI tests (demo/common/tests.cmake): its exit status,
# that stderr/stdout match a regular expression, and (for usage errors) that it printed one line.
#   cmake -DCOMMAND=a|b|c -DEXIT=2 -DSTDERR=regex [-DSTDOUT=regex] [-DONE_LINE=ON] -P expect_run.cmake
# (COMMAND's arguments are separated by '|', since add_test would split a ';' list.)
string(REPLACE "|" ";" command "${COMMAND}")
execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
set(shown "command: ${COMMAND}\nexit status: ${status}\nstdout:\n${out}\nstderr:\n${err}")
if(NOT status STREQUAL "${EXIT}")
  message(FATAL_ERROR "expected exit status ${EXIT}\n${shown}")
endif()
string(REGEX REPLACE "\n$" "" errText "${err}")  # so that a pattern may end with '$'
if(DEFINED STDERR AND NOT errText MATCHES "${STDERR}")
  message(FATAL_ERROR "stderr does not match '${STDERR}'\n${shown}")
endif()
if(DEFINED STDOUT AND NOT out MATCHES "${STDOUT}")
  message(FATAL_ERROR "stdout does not match '${STDOUT}'\n${shown}")
endif()
if(ONE_LINE)
  string(REGEX MATCHALL "\n" newlines "${err}")
  list(LENGTH newlines lines)
  if(NOT lines EQUAL 1 OR NOT out STREQUAL "")
    message(FATAL_ERROR "expected one line on stderr and nothing on stdout\n${shown}")
  endif()
endif()
