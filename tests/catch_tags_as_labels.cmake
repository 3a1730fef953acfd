# Gives every Catch2 test case its tags as CTest labels, so that
#   ctest -L verlet          runs exactly the [verlet] test cases
# (Catch2 v2's catch_discover_tests makes one CTest test per test case but
# drops the tags). Run after each build of the test program (POST_BUILD, see
# tests/CMakeLists.txt); it writes LABELS_FILE, which CTest includes after the
# discovered tests, one set_tests_properties() per test case.
#
#   cmake -D TEST_EXECUTABLE=<stepwise_tests> -D LABELS_FILE=<out.cmake> -P catch_tags_as_labels.cmake
#
# Catch2 prints long tag lists wrapped over several lines in --list-tests, so
# the tags come from --list-tags, and each tag's test cases from
# "[tag]" --list-test-names-only, which prints one unwrapped name per line:
# the same names catch_discover_tests gives the CTest tests.
cmake_minimum_required(VERSION 3.20)

execute_process(COMMAND "${TEST_EXECUTABLE}" --list-tags
                OUTPUT_VARIABLE tag_listing RESULT_VARIABLE listed)
if(listed LESS 0)
  message(FATAL_ERROR "catch_tags_as_labels: cannot run ${TEST_EXECUTABLE} --list-tags")
endif()
string(REGEX MATCHALL "\\[[^]\n]+\\]" tags "${tag_listing}")

set(test_keys "")
foreach(tag_in_brackets IN LISTS tags)
  string(REGEX REPLACE "^\\[(.*)\\]$" "\\1" tag "${tag_in_brackets}")
  # Hidden ([.]) and special ([!mayfail]) tags are switches, not stages.
  if(tag MATCHES "^[.!]")
    continue()
  endif()
  execute_process(COMMAND "${TEST_EXECUTABLE}" "[${tag}]" --list-test-names-only
                  OUTPUT_VARIABLE names RESULT_VARIABLE listed)
  string(REPLACE "\n" ";" names "${names}")
  foreach(name IN LISTS names)
    if(name STREQUAL "")
      continue()
    endif()
    # Test names may hold any character; a hash makes a safe variable name.
    string(MD5 key "${name}")
    if(NOT DEFINED name_${key})
      set(name_${key} "${name}")
      list(APPEND test_keys ${key})
    endif()
    list(APPEND labels_${key} "${tag}")
  endforeach()
endforeach()

set(script "# Written by tests/catch_tags_as_labels.cmake: Catch2 tags as CTest labels.\n")
foreach(key IN LISTS test_keys)
  string(APPEND script "set_tests_properties([==[${name_${key}}]==] PROPERTIES LABELS \"${labels_${key}}\")\n")
endforeach()
file(WRITE "${LABELS_FILE}" "${script}")
