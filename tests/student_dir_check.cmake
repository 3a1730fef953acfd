# CTest test "student-dir": STEPWISE_STUDENT_DIR swaps a student's file in for
# the engine's, and refuses a file that replaces nothing. Cheap on purpose: it
# configures a scratch build and compiles the one swapped-in file, not the
# whole engine (the full build and the stage's tests are the loop in
# lectures/student-template/README.md).
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

# 1. The template: its file replaces the engine's in the engine library.
configure_with("${TEMPLATE_DIR}" result output)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "configuring with the student template failed:\n${output}")
endif()
if(NOT output MATCHES "student file [^\n]*integrators/symplectic_euler.cpp replaces src/integrators/symplectic_euler.cpp")
  message(FATAL_ERROR "the configure output does not say the template replaces the engine's file:\n${output}")
endif()
file(READ "${SCRATCH_DIR}/compile_commands.json" commands)
if(NOT commands MATCHES "student-template/integrators/symplectic_euler.cpp")
  message(FATAL_ERROR "the student's file is not compiled")
endif()
if(commands MATCHES "src/integrators/symplectic_euler.cpp")
  message(FATAL_ERROR "the engine's own symplectic_euler.cpp is still compiled")
endif()
# Compile just that file, with warnings as errors ("file^" builds the object of a source).
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${SCRATCH_DIR}" --target "${TEMPLATE_DIR}/integrators/symplectic_euler.cpp^"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "the student template does not compile against the engine's headers:\n${output}${errors}")
endif()

# 2. A file that matches no engine file stops the configuration with a message naming it.
set(misnamed "${SCRATCH_DIR}-misnamed")
file(REMOVE_RECURSE "${misnamed}")
file(WRITE "${misnamed}/integrators/symplectic_eular.cpp" "// a typo in the name\n")
configure_with("${misnamed}" result output)
file(REMOVE_RECURSE "${misnamed}" "${SCRATCH_DIR}")
if(result EQUAL 0 OR NOT output MATCHES "symplectic_eular.cpp" OR NOT output MATCHES "replaces no engine file")
  message(FATAL_ERROR "a misnamed student file was not refused:\n${output}")
endif()
message(STATUS "student-dir: the template replaces src/integrators/symplectic_euler.cpp and compiles; a misnamed file is refused")
