# CTest test "install" (label install): the installed Stepwise works outside its source tree.
#
#   cmake -D BUILD_DIR=<build> -D SOURCE_DIR=<repo> -D SCRATCH_DIR=<dir> -D GENERATOR=<generator>
#         -D CXX=<compiler> -D VERSION=<project version> -P install_check.cmake
#
# 1. `cmake --install` of the build as it is (nothing is compiled again) into SCRATCH_DIR/prefix.
# 2. Every header installed includes only headers installed beside it, and the CMake package
#    names no file of the source or build tree, so the installed tree stands on its own.
# 3. A course's own project (tests/install_consumer/) finds the package with find_package(Stepwise):
#    a version of another minor is refused, this build's version is found in the scratch prefix,
#    and the package says how the engine was configured (single precision, fast path).
#    The project builds against Stepwise::engine and runs: a ball falls for 1 s and must be where
#    symplectic Euler puts it, within g·h·t/2 of y0 − g·t²/2 (tests/install_consumer/free_fall.cpp);
#    the headers, compiled there, make Real the type the build chose, and agree with the library
#    on the fast path's default.
# 4. The installed program, run from a folder with no config/ in it, opens the installed default
#    scene, not the source tree's.
cmake_minimum_required(VERSION 3.20)

foreach(variable BUILD_DIR SOURCE_DIR SCRATCH_DIR GENERATOR CXX VERSION)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "install_check.cmake: give -D ${variable}=…")
  endif()
endforeach()

set(prefix "${SCRATCH_DIR}/prefix")
set(consumer "${SCRATCH_DIR}/consumer")
file(REMOVE_RECURSE "${SCRATCH_DIR}")
file(MAKE_DIRECTORY "${SCRATCH_DIR}")

# run(<what> <command>…): runs the command, stops the test with its output when it fails,
# and leaves the output in run_output.
function(run what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors
                  WORKING_DIRECTORY "${SCRATCH_DIR}")
  if(NOT result EQUAL 0)
    message(FATAL_ERROR "install: ${what} failed (${result}):\n${output}${errors}")
  endif()
  set(run_output "${output}${errors}" PARENT_SCOPE)
endfunction()

# 1. Install the build.
run("cmake --install" "${CMAKE_COMMAND}" --install "${BUILD_DIR}" --prefix "${prefix}")

# 2. What a course's project and a student need is there, and it names nothing outside the prefix.
file(GLOB program "${prefix}/bin/stepwise")
file(GLOB_RECURSE library "${prefix}/*/libstepwise_engine.a")
file(GLOB_RECURSE config "${prefix}/*/StepwiseConfig.cmake")
file(GLOB_RECURSE version_file "${prefix}/*/StepwiseConfigVersion.cmake")
file(GLOB_RECURSE default_scene "${prefix}/*/stepwise/config/default.scene")
foreach(part program library config version_file default_scene)
  if(NOT ${part})
    message(FATAL_ERROR "install: nothing installed for ${part} below ${prefix}")
  endif()
endforeach()

set(include_dir "${prefix}/include/stepwise")
file(GLOB_RECURSE headers RELATIVE "${include_dir}" "${include_dir}/*")
list(LENGTH headers header_count)
if(header_count EQUAL 0 OR NOT EXISTS "${include_dir}/world/world.hpp")
  message(FATAL_ERROR "install: no world/world.hpp below ${include_dir}")
endif()
foreach(header IN LISTS headers)
  if(header MATCHES "^(app|viewer)/")
    message(FATAL_ERROR "install: ${header} is the program's, not the engine's: it must not be installed")
  endif()
  # Quoted includes are the engine's own ("world/world.hpp"): each must be installed too.
  file(STRINGS "${include_dir}/${header}" includes REGEX "^[ \t]*#[ \t]*include[ \t]*\"")
  foreach(line IN LISTS includes)
    string(REGEX REPLACE "^[^\"]*\"([^\"]+)\".*$" "\\1" included "${line}")
    if(NOT EXISTS "${include_dir}/${included}")
      message(FATAL_ERROR "install: the installed ${header} includes \"${included}\", which is not installed")
    endif()
  endforeach()
endforeach()

get_filename_component(config_dir "${config}" DIRECTORY)
file(GLOB package_files "${config_dir}/*.cmake")
foreach(file IN LISTS package_files)
  file(READ "${file}" text)
  foreach(tree "${SOURCE_DIR}" "${BUILD_DIR}")
    string(FIND "${text}" "${tree}" at)
    if(NOT at EQUAL -1)
      message(FATAL_ERROR "install: ${file} names ${tree}: the installed package must not need the tree it was built in")
    endif()
  endforeach()
endforeach()

# 3. A course's own project. First a version of the next minor, which this package must refuse.
string(REGEX MATCH "^([0-9]+)\\.([0-9]+)" _ "${VERSION}")
math(EXPR next_minor "${CMAKE_MATCH_2} + 1")
set(configure_consumer "${CMAKE_COMMAND}" -S "${SOURCE_DIR}/tests/install_consumer" -B "${consumer}"
    -G "${GENERATOR}" "-DCMAKE_CXX_COMPILER=${CXX}" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_PREFIX_PATH=${prefix}")
execute_process(COMMAND ${configure_consumer} "-DSTEPWISE_VERSION_WANTED=${CMAKE_MATCH_1}.${next_minor}"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(result EQUAL 0 OR NOT "${output}${errors}" MATCHES "compatible with requested version")
  message(FATAL_ERROR "install: find_package(Stepwise ${CMAKE_MATCH_1}.${next_minor}) did not refuse "
                      "version ${VERSION}:\n${output}${errors}")
endif()

run("configuring tests/install_consumer" ${configure_consumer} "-DSTEPWISE_VERSION_WANTED=${VERSION}")
# The package's variables say how this build was configured (the options in its CMakeCache.txt).
file(STRINGS "${BUILD_DIR}/CMakeCache.txt" single REGEX "^STEPWISE_SINGLE_PRECISION:")
file(STRINGS "${BUILD_DIR}/CMakeCache.txt" fast REGEX "^STEPWISE_FAST_PATH:")
string(REGEX REPLACE "^[^=]*=" "" single "${single}")
string(REGEX REPLACE "^[^=]*=" "" fast "${fast}")
if(NOT run_output MATCHES "single precision ([A-Za-z]+), fast path ([A-Za-z]+)"
   OR NOT CMAKE_MATCH_1 STREQUAL single OR NOT CMAKE_MATCH_2 STREQUAL fast)
  message(FATAL_ERROR "install: the package says \"${CMAKE_MATCH_0}\"; the build was configured with "
                      "STEPWISE_SINGLE_PRECISION=${single}, STEPWISE_FAST_PATH=${fast}:\n${run_output}")
endif()
file(STRINGS "${consumer}/CMakeCache.txt" found REGEX "^Stepwise_DIR:")
string(REGEX REPLACE "^[^=]*=" "" found "${found}")
file(REAL_PATH "${found}" found)
file(REAL_PATH "${config_dir}" expected)
if(NOT found STREQUAL expected)
  message(FATAL_ERROR "install: find_package(Stepwise) found ${found}, not the package installed in ${expected}")
endif()
run("building tests/install_consumer" "${CMAKE_COMMAND}" --build "${consumer}")
run("free_fall (tests/install_consumer/free_fall.cpp)" "${consumer}/free_fall")
if(NOT run_output MATCHES "free_fall: PASS")
  message(FATAL_ERROR "install: free_fall did not say PASS:\n${run_output}")
endif()
# The project's Real is the one the build chose: float with STEPWISE_SINGLE_PRECISION, else double.
if(single)
  set(real_size 4)
else()
  set(real_size 8)
endif()
if(NOT run_output MATCHES "sizeof\\(Real\\) = ${real_size},")
  message(FATAL_ERROR "install: STEPWISE_SINGLE_PRECISION=${single}, but the project outside the tree "
                      "does not see a Real of ${real_size} bytes:\n${run_output}")
endif()
message(STATUS "install: the project outside the tree ran the installed engine:\n${run_output}")

# 4. The installed program opens the installed default scene. SCRATCH_DIR, where it runs, has no config/.
run("${program} run --steps 1" "${program}" run --steps 1)
string(REGEX MATCH "Scene ([^\n]*)" _ "${run_output}")
set(opened "${CMAKE_MATCH_1}")
file(REAL_PATH "${default_scene}" installed_scene)
if(opened STREQUAL "" OR NOT EXISTS "${opened}")
  message(FATAL_ERROR "install: the installed program did not open a default scene:\n${run_output}")
endif()
file(REAL_PATH "${opened}" opened)
if(NOT opened STREQUAL installed_scene)
  message(FATAL_ERROR "install: the installed program opened ${opened}, not its installed ${installed_scene}")
endif()
message(STATUS "install: ${header_count} headers; the installed program opens ${opened}")
