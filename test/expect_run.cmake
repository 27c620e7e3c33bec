# Runs a program as a test that fails unless the program exits with status 0, its standard
# output matches PATTERN and the file WRITES (if given) exists afterwards. CTest's
# PASS_REGULAR_EXPRESSION alone would ignore the exit status (issue 45). COMMAND separates the
# program and its arguments with '|'.
#   cmake "-DCOMMAND=program|arg|..." "-DPATTERN=regex" [-DWRITES=file] -P test/expect_run.cmake
string(REPLACE "|" ";" command "${COMMAND}")
if(WRITES)
  file(REMOVE "${WRITES}")
endif()
execute_process(COMMAND ${command} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "exited with status ${status}:\n${out}${err}")
endif()
if(WRITES AND NOT EXISTS "${WRITES}")
  message(FATAL_ERROR "did not write ${WRITES}:\n${out}${err}")
endif()
if(NOT out MATCHES "${PATTERN}")
  message(FATAL_ERROR "the output does not match '${PATTERN}':\n${out}${err}")
endif()
message(STATUS "${out}")
