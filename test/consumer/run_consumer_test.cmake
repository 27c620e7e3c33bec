# cmake -DPSC_SOURCE_DIR=... -DPSC_BINARY_DIR=... -DPSC_MODE=installed|subdirectory -P run_consumer_test.cmake
#
# installed:    installs the build tree PSC_BINARY_DIR into a fresh prefix, then configures,
#               builds and runs test/consumer against it with find_package();
# subdirectory: configures, builds and runs test/consumer with add_subdirectory() of the
#               source tree.
# Fails on the first step that fails, with its output.
set(work ${PSC_BINARY_DIR}/consumer_test/${PSC_MODE})
file(REMOVE_RECURSE ${work})
function(step)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT rc EQUAL 0)
    message(FATAL_ERROR "step failed (${rc}): ${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${out}")
endfunction()
set(configure ${CMAKE_COMMAND} -S ${PSC_SOURCE_DIR}/test/consumer -B ${work}/build -DCMAKE_BUILD_TYPE=Release
              -DPSC_CONSUMER_MODE=${PSC_MODE})
if(PSC_MODE STREQUAL "installed")
  step(${CMAKE_COMMAND} --install ${PSC_BINARY_DIR} --prefix ${work}/prefix)
  if(NOT EXISTS ${work}/prefix/include/CGAL/estimate_aso_curvatures.h)
    message(FATAL_ERROR "the headers were not installed")
  endif()
  step(${configure} -DCMAKE_PREFIX_PATH=${work}/prefix)
else()
  step(${configure} -DPSC_SOURCE_DIR=${PSC_SOURCE_DIR})
endif()
step(${CMAKE_COMMAND} --build ${work}/build --target consumer)
step(${work}/build/consumer)
