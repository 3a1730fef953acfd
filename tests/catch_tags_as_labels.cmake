# Gives every Catch2 test case its tags as CTest labels, so that
#   ctest -L verlet          runs exactly the [verlet] test cases
# (Catch2 v2's catch_discover_tests makes one CTest test per test case but
# drops the tags). Run after each build of the test program (POST_BUILD, see
# tests/CMakeLists.txt); it writes LABELS_FILE, which CTest includes after the
# discovered tests, one set_tests_properties() per test case.
#
#   cmake -D TEST_EXECUTABLE=<stepwise_tests> -D LABELS_FILE=<out.cmake> -P catch_tags_as_labels.cmake
#
# The tags and names come from one run of the program's own listing, `--list-labels` (tests/main.cpp):
# one line per test case, its tags "[a][b]", a tab, its name; the names are the ones
# catch_discover_tests gives the CTest tests (Catch2's --list-test-names-only prints the same).
cmake_minimum_required(VERSION 3.20)

execute_process(COMMAND "${TEST_EXECUTABLE}" --list-labels
                OUTPUT_VARIABLE listing RESULT_VARIABLE listed)
if(NOT listed EQUAL 0)
  message(FATAL_ERROR "catch_tags_as_labels: ${TEST_EXECUTABLE} --list-labels failed (${listed})")
endif()
string(REPLACE "\n" ";" lines "${listing}")

set(test_keys "")
foreach(line IN LISTS lines)
  string(FIND "${line}" "\t" tab)
  if(tab LESS 0)
    continue()
  endif()
  string(SUBSTRING "${line}" 0 ${tab} tag_text)
  math(EXPR name_start "${tab} + 1")
  string(SUBSTRING "${line}" ${name_start} -1 name)
  # Test names may hold any character; a hash makes a safe variable name.
  string(MD5 key "${name}")
  set(name_${key} "${name}")
  set(labels_${key} "")
  string(REGEX MATCHALL "\\[[^]]+\\]" tags "${tag_text}")
  foreach(tag_in_brackets IN LISTS tags)
    string(REGEX REPLACE "^\\[(.*)\\]$" "\\1" tag "${tag_in_brackets}")
    # Hidden ([.]) and special ([!mayfail]) tags are switches, not stages.
    if(tag MATCHES "^[.!]")
      continue()
    endif()
    list(APPEND labels_${key} "${tag}")
  endforeach()
  if(labels_${key})
    list(APPEND test_keys ${key})
  endif()
endforeach()

set(script "# Written by tests/catch_tags_as_labels.cmake: Catch2 tags as CTest labels.\n")
foreach(key IN LISTS test_keys)
  string(APPEND script "set_tests_properties([==[${name_${key}}]==] PROPERTIES LABELS \"${labels_${key}}\")\n")
endforeach()
file(WRITE "${LABELS_FILE}" "${script}")
