# CTest tests "student-template:<file>" and "student-answer:<file>" (tests/student_templates.cmake):
# build the test program with one stage swapped in, run that stage's tests, and check the outcome.
#
#   cmake -D BUILD_DIR=<build tree> -D TARGET=<test program target> -D EXECUTABLE=<its path>
#         -D SOURCE_DIR=<repository> -D SWAPPED_IN=<the .cpp swapped in> -D FILE=<path below src/>
#         -D TAGS=<Catch2 test spec> -D NAMES=<function,…> -D EXPECT=fail|pass -P student_stage_check.cmake
#
# EXPECT=fail (an untouched template): it links, at least one of the stage's tests fails, and
# the output carries "student stage not written yet: stepwise::<name>" for every name in NAMES.
# EXPECT=pass (the answer): it links and every test of the stage passes.
# Either way the test spec must match at least one test case: Catch2 v2 exits 0 when a spec
# matches nothing ("No tests ran"), so the tests run with --warn NoTests and the count is read.
cmake_minimum_required(VERSION 3.20)

file(RELATIVE_PATH shown "${SOURCE_DIR}" "${SWAPPED_IN}")
string(REPLACE "," ";" names "${NAMES}")

# 1. Build (compile the swapped-in file, link the engine's other objects and the tests' objects).
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${BUILD_DIR}" --target "${TARGET}" --parallel 2
                RESULT_VARIABLE built OUTPUT_VARIABLE build_output ERROR_VARIABLE build_output)
if(NOT built EQUAL 0)
  # The lines that say why (the compiler's errors, the linker's undefined references), else all of it.
  string(REGEX MATCHALL "[^\n]*(error:|undefined reference)[^\n]*" reasons "${build_output}")
  if(reasons)
    list(REMOVE_DUPLICATES reasons)
    list(JOIN reasons "\n" build_output)
  endif()
  set(problem "does not build")
  if(build_output MATCHES "undefined reference")
    set(problem "does not link: the rest of the engine calls a function the file does not define")
  endif()
  message(FATAL_ERROR "${shown} swapped in for src/${FILE}: the engine ${problem}:\n${build_output}")
endif()

# 2. The stage's tests, in one process, as `stepwise_tests "<spec>"` runs them.
execute_process(COMMAND "${EXECUTABLE}" "${TAGS}" --warn NoTests
                WORKING_DIRECTORY "${SOURCE_DIR}"
                RESULT_VARIABLE ran OUTPUT_VARIABLE output ERROR_VARIABLE output)
set(cases 0)
if(output MATCHES "in ([0-9]+) test cases?\\)")        # All tests passed (N assertions in M test cases)
  set(cases "${CMAKE_MATCH_1}")
elseif(output MATCHES "test cases: *([0-9]+)")         # test cases: M | P passed | F failed
  set(cases "${CMAKE_MATCH_1}")
endif()
if(cases EQUAL 0)
  message(FATAL_ERROR "${shown}: the test spec '${TAGS}' ran no test case (exit ${ran}):\n${output}")
endif()

if(EXPECT STREQUAL "pass")
  if(NOT ran EQUAL 0)
    message(FATAL_ERROR "${shown} swapped in for src/${FILE}: the '${TAGS}' tests fail (exit ${ran}):\n${output}")
  endif()
  message(STATUS "${shown} swapped in for src/${FILE}: links, and the ${cases} '${TAGS}' test cases pass")
  return()
endif()

if(ran EQUAL 0)
  message(FATAL_ERROR "${shown} (untouched) swapped in for src/${FILE}: the ${cases} '${TAGS}' test cases "
                      "pass, but an unwritten stage must fail them:\n${output}")
endif()
foreach(name IN LISTS names)
  if(NOT output MATCHES "student stage not written yet: stepwise::${name}[ \n]")
    message(FATAL_ERROR "${shown} (untouched) swapped in for src/${FILE}: the '${TAGS}' tests fail (exit ${ran}), "
                        "but no failure says \"student stage not written yet: stepwise::${name} …\":\n${output}")
  endif()
endforeach()
set(failed "?")
if(output MATCHES "test cases: *[0-9]+ \\|[^\n]*\\| *([0-9]+) failed")
  set(failed "${CMAKE_MATCH_1}")
elseif(output MATCHES "test cases: *[0-9]+ \\| *([0-9]+) failed")
  set(failed "${CMAKE_MATCH_1}")
endif()
string(REGEX MATCH "student stage not written yet: stepwise::[A-Za-z_0-9]*" first_message "${output}")
message(STATUS "${shown} (untouched) swapped in for src/${FILE}: links; ${failed} of the ${cases} '${TAGS}' "
               "test cases fail with \"${first_message} …\"")
