# The student loop, checked end to end (lectures/student-template/README.md).
#
#   stepwise_student_stage(<file> TAGS <Catch2 test spec> NAMES <function>...)
#
# declares one stage students rewrite: lectures/student-template/<file> replaces
# src/<file>. With STEPWISE_CHECK_STUDENT_TEMPLATES ON (the ci preset) it adds
# two CTest tests, labelled "student":
#
#   student-template:<file>  the engine with the untouched template swapped in links,
#                            and the stage's tests (TAGS) fail with the TODO's message,
#                            "student stage not written yet: stepwise::<name>", for each of NAMES
#   student-answer:<file>    the engine with the instructors' answer swapped in
#                            (lectures/instructors/student-template-answers/<file>) links,
#                            and the stage's tests pass
#
# Nothing is compiled twice: the engine and the tests are object libraries
# (stepwise_engine_objects, stepwise_tests_objects), and each swap is a static
# library of the engine's objects without src/<file>'s ($<FILTER>) plus the
# swapped-in file's, linked with the tests' objects. Those targets are
# EXCLUDE_FROM_ALL: each test builds its own (tests/student_stage_check.cmake),
# so a template that does not link fails its test, not the build. The tests
# share one RESOURCE_LOCK, since two builds must not run in one build tree at once.

set(STEPWISE_STUDENT_TEMPLATE_DIR "${PROJECT_SOURCE_DIR}/lectures/student-template")
set(STEPWISE_STUDENT_ANSWER_DIR "${PROJECT_SOURCE_DIR}/lectures/instructors/student-template-answers")
# The students' copy of the repository leaves the answers out (docs/instructors.md).
if(IS_DIRECTORY "${STEPWISE_STUDENT_ANSWER_DIR}")
  set(STEPWISE_HAVE_STUDENT_ANSWERS ON)
else()
  set(STEPWISE_HAVE_STUDENT_ANSWERS OFF)
endif()
set_property(GLOBAL PROPERTY STEPWISE_STUDENT_STAGES "")

function(stepwise_student_stage file)
  cmake_parse_arguments(PARSE_ARGV 1 stage "" "TAGS" "NAMES")
  if(NOT stage_TAGS OR NOT stage_NAMES)
    message(FATAL_ERROR "stepwise_student_stage(${file}): give TAGS and NAMES")
  endif()
  if(NOT EXISTS "${PROJECT_SOURCE_DIR}/src/${file}")
    message(FATAL_ERROR "stepwise_student_stage(${file}): there is no src/${file} for the template to replace")
  endif()
  if(NOT EXISTS "${STEPWISE_STUDENT_TEMPLATE_DIR}/${file}")
    message(FATAL_ERROR "stepwise_student_stage(${file}): there is no lectures/student-template/${file}")
  endif()
  if(STEPWISE_HAVE_STUDENT_ANSWERS AND NOT EXISTS "${STEPWISE_STUDENT_ANSWER_DIR}/${file}")
    message(FATAL_ERROR "stepwise_student_stage(${file}): there is no answer "
                        "lectures/instructors/student-template-answers/${file}")
  endif()
  set_property(GLOBAL APPEND PROPERTY STEPWISE_STUDENT_STAGES "${file}")
  if(NOT STEPWISE_CHECK_STUDENT_TEMPLATES)
    return()
  endif()

  string(MAKE_C_IDENTIFIER "${file}" id)
  list(JOIN stage_NAMES "," names)  # a ';' would split the test's command line
  # The engine's object of src/<file>, e.g. …/stepwise_engine_objects.dir/src/collision/box_box.cpp.o
  string(REPLACE "." "[.]" escaped "${file}")
  set(engine_object "/src/${escaped}[.]o$")
  set(kinds template)
  if(STEPWISE_HAVE_STUDENT_ANSWERS)
    list(APPEND kinds answer)
  endif()
  foreach(kind IN LISTS kinds)
    if(kind STREQUAL "template")
      set(source "${STEPWISE_STUDENT_TEMPLATE_DIR}/${file}")
      set(expect fail)
    else()
      set(source "${STEPWISE_STUDENT_ANSWER_DIR}/${file}")
      set(expect pass)
    endif()
    set(name student_${kind}_${id})
    add_library(${name}_object OBJECT EXCLUDE_FROM_ALL "${source}")
    target_link_libraries(${name}_object PRIVATE stepwise_engine_objects stepwise_options)
    add_library(${name}_engine STATIC EXCLUDE_FROM_ALL
      "$<FILTER:$<TARGET_OBJECTS:stepwise_engine_objects>,EXCLUDE,${engine_object}>"
      $<TARGET_OBJECTS:${name}_object>)
    target_link_libraries(${name}_engine INTERFACE stepwise_engine_objects)
    add_executable(${name}_tests EXCLUDE_FROM_ALL $<TARGET_OBJECTS:stepwise_tests_objects>)
    target_link_libraries(${name}_tests PRIVATE stepwise_command_line ${name}_engine stepwise_options Catch2::Catch2)
    add_test(NAME student-${kind}:${file}
      COMMAND "${CMAKE_COMMAND}" -D "BUILD_DIR=${PROJECT_BINARY_DIR}" -D "TARGET=${name}_tests"
              -D "EXECUTABLE=$<TARGET_FILE:${name}_tests>" -D "SOURCE_DIR=${PROJECT_SOURCE_DIR}"
              -D "SWAPPED_IN=${source}" -D "FILE=${file}" -D "TAGS=${stage_TAGS}" -D "NAMES=${names}"
              -D "EXPECT=${expect}" -P "${CMAKE_CURRENT_SOURCE_DIR}/student_stage_check.cmake")
    set_tests_properties(student-${kind}:${file} PROPERTIES LABELS "student" RESOURCE_LOCK stepwise-build-tree)
  endforeach()
endfunction()

# After the table: every template has its line in it, and each answer equals its
# template outside the YOUR CODE regions (student-answers-match).
function(stepwise_student_stages_done)
  get_property(declared GLOBAL PROPERTY STEPWISE_STUDENT_STAGES)
  file(GLOB_RECURSE templates RELATIVE "${STEPWISE_STUDENT_TEMPLATE_DIR}" CONFIGURE_DEPENDS
       "${STEPWISE_STUDENT_TEMPLATE_DIR}/*.cpp")
  foreach(file IN LISTS templates)
    if(NOT file IN_LIST declared)
      message(FATAL_ERROR "lectures/student-template/${file} has no stepwise_student_stage() line in tests/CMakeLists.txt")
    endif()
  endforeach()
  if(STEPWISE_HAVE_STUDENT_ANSWERS)
    add_test(NAME student-answers-match
      COMMAND "${CMAKE_COMMAND}" -D "TEMPLATE_DIR=${STEPWISE_STUDENT_TEMPLATE_DIR}"
              -D "ANSWER_DIR=${STEPWISE_STUDENT_ANSWER_DIR}" -P "${CMAKE_CURRENT_SOURCE_DIR}/student_answers_match.cmake")
    set_tests_properties(student-answers-match PROPERTIES LABELS "student")
  endif()
  if(STEPWISE_CHECK_STUDENT_TEMPLATES)
    message(STATUS "Stepwise: student templates checked by linking (ctest -L student): ${declared}")
    if(NOT STEPWISE_HAVE_STUDENT_ANSWERS)
      message(STATUS "Stepwise: no lectures/instructors/student-template-answers: only the untouched templates are checked")
    endif()
  endif()
endfunction()
