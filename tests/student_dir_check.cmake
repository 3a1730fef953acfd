# CTest test "student-dir": STEPWISE_STUDENT_DIR swaps a student's files in for
# the engine's, and refuses a file that replaces nothing. Cheap on purpose: it
# only configures a scratch build with the whole template folder and reads
# what it would compile. Whether each template links and what its stage's
# tests then say is the student-template:<file> tests' job
# (tests/student_templates.cmake).
#
#   cmake -D SOURCE_DIR=<repo> -D SCRATCH_DIR=<dir> -D TEMPLATE_DIR=<template>
#         -D GENERATOR=<generator> -D CXX=<compiler> -P student_dir_check.cmake
cmake_minimum_required(VERSION 3.20)

function(configure_with student_dir result_var output_var)
  file(REMOVE_RECURSE "${SCRATCH_DIR}")
  execute_process(
    COMMAND "${CMAKE_COMMAND}" -S "${SOURCE_DIR}" -B "${SCRATCH_DIR}" -G "${GENERATOR}"
            "-DCMAKE_CXX_COMPILER=${CXX}" -DCMAKE_BUILD_TYPE=Release -DSTEPWISE_WERROR=ON
            -DSTEPWISE_BUILD_TESTS=OFF -DSTEPWISE_VIEWER=OFF "-DSTEPWISE_STUDENT_DIR=${student_dir}"
    RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
  set(${result_var} "${result}" PARENT_SCOPE)
  set(${output_var} "${output}${errors}" PARENT_SCOPE)
endfunction()

# 1. The templates: each file replaces the engine's of the same path in the engine library.
configure_with("${TEMPLATE_DIR}" result output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "configuring with the student templates failed:\n${output}")
endif()
file(READ "${SCRATCH_DIR}/compile_commands.json" commands)
file(GLOB_RECURSE templates RELATIVE "${TEMPLATE_DIR}" "${TEMPLATE_DIR}/*.cpp")
if(NOT templates)
  message(FATAL_ERROR "no .cpp file in ${TEMPLATE_DIR}")
endif()
foreach(relative IN LISTS templates)
  if(NOT output MATCHES "student file [^\n]*/${relative} replaces src/${relative}")
    message(FATAL_ERROR "the configure output does not say ${relative} replaces src/${relative}:\n${output}")
  endif()
  if(NOT commands MATCHES "student-template/${relative}")
    message(FATAL_ERROR "the student's ${relative} is not compiled")
  endif()
  if(commands MATCHES "src/${relative}")
    message(FATAL_ERROR "the engine's own src/${relative} is still compiled")
  endif()
endforeach()

# 2. A file that matches no engine file stops the configuration with a message naming it.
set(misnamed "${SCRATCH_DIR}-misnamed")
file(REMOVE_RECURSE "${misnamed}")
file(WRITE "${misnamed}/integrators/symplectic_eular.cpp" "// a typo in the name\n")
configure_with("${misnamed}" result output)
file(REMOVE_RECURSE "${misnamed}" "${SCRATCH_DIR}")
if(result EQUAL 0 OR NOT output MATCHES "symplectic_eular.cpp" OR NOT output MATCHES "replaces no engine file")
  message(FATAL_ERROR "a misnamed student file was not refused:\n${output}")
endif()
list(LENGTH templates count)
message(STATUS "student-dir: the ${count} templates replace the engine's files of their paths; a misnamed file is refused")
