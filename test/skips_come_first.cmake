# A test case that skips (skip_test() of test_tool.cpp prints PSC_TEST_SKIPPED, which CTest
# turns into a skip and then ignores the exit status) must not have asserted anything before:
# a failure before the skip would be hidden. Checked here on the source, for every test case
# of SOURCES (a ';'-separated list) that calls skip_test("..."): no CHECK, REQUIRE, SUCCEED or
# FAIL macro before its first call (the helpers it calls before are not looked into: they
# must not assert either, as the comment on skip_test() says).
#
#   cmake -DSOURCES=test/test_tool.cpp -P test/skips_come_first.cmake
foreach(source IN LISTS SOURCES)
  file(READ "${source}" text)
  set(offenders "")
  set(cases 0)
  string(FIND "${text}" "TEST_CASE(\"" at)
  while(NOT at EQUAL -1)
    string(SUBSTRING "${text}" ${at} -1 rest)
    string(SUBSTRING "${rest}" 1 -1 after)
    string(FIND "${after}" "TEST_CASE(\"" next)
    if(next EQUAL -1)
      set(body "${rest}")
    else()
      math(EXPR length "${next} + 1")
      string(SUBSTRING "${rest}" 0 ${length} body)
    endif()
    string(FIND "${body}" "skip_test(\"" skip)
    if(NOT skip EQUAL -1)
      math(EXPR cases "${cases} + 1")
      string(SUBSTRING "${body}" 0 ${skip} before)
      string(FIND "${before}" "\n" name_end)
      string(SUBSTRING "${before}" 0 ${name_end} name)
      if(before MATCHES "(CHECK|REQUIRE|SUCCEED|FAIL)[A-Z_]*\\(")
        string(APPEND offenders "\n  ${name}")
      endif()
    endif()
    if(next EQUAL -1)
      set(at -1)
    else()
      math(EXPR at "${at} + ${next} + 1")
    endif()
  endwhile()
  if(offenders)
    message(FATAL_ERROR "${source}: test cases that assert before skip_test() (a skip would hide their failures):${offenders}")
  endif()
  message(STATUS "${source}: ${cases} test cases skip before asserting anything")
endforeach()
