# CTest test "catch2-count": every Catch2 test case of the test program is registered with CTest.
#
# catch_discover_tests (tests/CMakeLists.txt) makes one CTest test per test case, with the test
# case's name as its filter. A name CTest treats specially (a ';' cuts it in two) would register a
# test that runs nothing, and one that starts with '-' is read as an option; --warn NoTests makes
# such a test fail, and this check refuses both names and makes sure the two
# counts agree, so no test case is left out either.
#
#   cmake -D TEST_EXECUTABLE=<stepwise_tests> -D CTEST=<ctest> -D BUILD_DIR=<build> -P catch_count_check.cmake
cmake_minimum_required(VERSION 3.20)

execute_process(COMMAND "${TEST_EXECUTABLE}" --list-test-names-only OUTPUT_VARIABLE names RESULT_VARIABLE listed)
if(NOT listed EQUAL 0 AND listed LESS 0)
  message(FATAL_ERROR "catch2-count: cannot run ${TEST_EXECUTABLE} --list-test-names-only")
endif()
string(REGEX MATCHALL "[^\n]+" cases "${names}")
list(LENGTH cases catch_count)
foreach(name IN LISTS cases)
  if(name MATCHES ";")
    message(FATAL_ERROR "catch2-count: the test case \"${name}\" has a ';' in its name, which CTest cuts in two: rename it")
  endif()
  if(name MATCHES "^-")
    message(FATAL_ERROR "catch2-count: the test case \"${name}\" starts with '-', which the test program reads as an option: rename it")
  endif()
endforeach()

execute_process(COMMAND "${CTEST}" -N -L "^catch2$" WORKING_DIRECTORY "${BUILD_DIR}" OUTPUT_VARIABLE listing)
string(REGEX MATCH "Total Tests: ([0-9]+)" _ "${listing}")
set(ctest_count "${CMAKE_MATCH_1}")
if(NOT catch_count EQUAL ctest_count)
  message(FATAL_ERROR "catch2-count: the test program has ${catch_count} test cases, CTest registers ${ctest_count} "
                      "(label catch2): some test case would not run")
endif()
if(catch_count LESS 100)
  message(FATAL_ERROR "catch2-count: only ${catch_count} test cases listed: the listing failed")
endif()
message(STATUS "catch2-count: ${catch_count} Catch2 test cases, ${ctest_count} CTest tests: each runs once")
