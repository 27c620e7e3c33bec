# Checks that the C++ program of README.md (its first ```cpp block) is examples/readme_program.cpp
# below its three comment lines, so that the program the README shows is the one CTest builds
# and runs (example_readme_program).
#   cmake -DREADME=README.md -DPROGRAM=examples/readme_program.cpp -P test/readme_program.cmake
file(READ "${README}" readme)
file(READ "${PROGRAM}" program)
string(FIND "${readme}" "```cpp\n" begin)
if(begin EQUAL -1)
  message(FATAL_ERROR "${README} has no ```cpp block")
endif()
math(EXPR begin "${begin} + 7")
string(SUBSTRING "${readme}" ${begin} -1 rest)
string(FIND "${rest}" "```" end)
string(SUBSTRING "${rest}" 0 ${end} shown)
# the program without its first three lines (copyright, licence, what it is) and the blank line
string(REGEX REPLACE "^//[^\n]*\n//[^\n]*\n//[^\n]*\n\n" "" built "${program}")
if(NOT shown STREQUAL built)
  message(FATAL_ERROR "the README's C++ program differs from ${PROGRAM}: copy one to the other")
endif()
message(STATUS "the README's C++ program is ${PROGRAM}")
