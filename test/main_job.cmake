# The README's main job as a test: the tool on the shipped Goursat cloud must exit with status 0,
# write its output and report every point valid. (CTest's PASS_REGULAR_EXPRESSION alone would
# ignore the exit status: issue 45.)
#   cmake -DTOOL=... -DINPUT=data/goursat_010000.xyz -DOUTPUT=goursat_curvatures.ply -P test/main_job.cmake
file(REMOVE "${OUTPUT}")
execute_process(COMMAND "${TOOL}" "${INPUT}" "${OUTPUT}" --radius 1.5 --color mean
                RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "the tool exited with status ${status}:\n${out}${err}")
endif()
if(NOT EXISTS "${OUTPUT}")
  message(FATAL_ERROR "the tool did not write ${OUTPUT}:\n${out}${err}")
endif()
if(NOT out MATCHES "valid +10000 \\(100.00 %\\)")
  message(FATAL_ERROR "the summary does not say that all 10000 points are valid:\n${out}${err}")
endif()
message(STATUS "${out}")
