# Swap in a student's own implementation of engine stages, without editing src/.
#
#   cmake --preset student                                  # the folder student/ at the top of the repository
#   cmake -S . -B build/mine -DSTEPWISE_STUDENT_DIR=PATH    # any folder
#
# Every .cpp file below STEPWISE_STUDENT_DIR replaces the engine file with the
# same path below src/: PATH/integrators/symplectic_euler.cpp is compiled
# instead of src/integrators/symplectic_euler.cpp, and everything built from
# the engine (the stepwise program, the tests) uses it. Headers are not
# replaced: they are the interface the rest of the engine calls, so a
# student's file implements the same functions (lectures/student-template/
# has one template per stage the lectures ask students to write).
# A file that matches no engine file stops the configuration, so a typo in a
# file name cannot silently leave the engine's own stage in place.

set(STEPWISE_STUDENT_DIR "" CACHE PATH
    "Folder of a student's stage files; each replaces the engine file of the same path below src/ (docs/instructors.md)")

# stepwise_swap_in_student_files(<list variable of absolute engine .cpp paths>)
function(stepwise_swap_in_student_files sources_var)
  if(NOT STEPWISE_STUDENT_DIR)
    return()
  endif()
  get_filename_component(student_dir "${STEPWISE_STUDENT_DIR}" ABSOLUTE)
  if(NOT IS_DIRECTORY "${student_dir}")
    message(FATAL_ERROR "STEPWISE_STUDENT_DIR: '${student_dir}' is not a folder "
                        "(copy a template from lectures/student-template there to start)")
  endif()
  file(GLOB_RECURSE student_files RELATIVE "${student_dir}" CONFIGURE_DEPENDS "${student_dir}/*.cpp")
  if(NOT student_files)
    message(FATAL_ERROR "STEPWISE_STUDENT_DIR: '${student_dir}' has no .cpp files; name each one after the engine "
                        "file it replaces, e.g. integrators/symplectic_euler.cpp for src/integrators/symplectic_euler.cpp")
  endif()
  set(sources ${${sources_var}})
  foreach(relative IN LISTS student_files)
    set(engine_file "${PROJECT_SOURCE_DIR}/src/${relative}")
    list(FIND sources "${engine_file}" index)
    if(index EQUAL -1)
      message(FATAL_ERROR "STEPWISE_STUDENT_DIR: ${student_dir}/${relative} replaces no engine file: there is no "
                          "src/${relative} in the engine (files of src/app and src/viewer cannot be replaced)")
    endif()
    list(REMOVE_AT sources ${index})
    list(APPEND sources "${student_dir}/${relative}")
    message(STATUS "Stepwise: student file ${student_dir}/${relative} replaces src/${relative}")
  endforeach()
  set(${sources_var} ${sources} PARENT_SCOPE)
endfunction()
