# CTest test "scene-hashes": every shipped scene still computes what it computed.
#
# Runs `stepwise run SCENE --csv FILE` on every scene below config/ and
# lectures/ and compares the SHA-256 of each trajectory (every body's
# position, velocity, orientation and angular velocity, printed with 17
# significant digits, so a change in the last bit of any of them changes the
# hash) with the list in tests/data/scene_hashes.txt.
#
# Why: the engine has two roads through a step, the plain one a student reads
# and the fast wing (src/fast/), which must compute the same numbers bit for
# bit; and a restructuring, a comment clean-up or a move of files must not
# change what the engine computes at all. A change that is meant to change
# the physics updates the list in the same commit, and says so:
#
#   cmake -D STEPWISE=build/ci/stepwise -D SOURCE_DIR=. -D SCRATCH_DIR=/tmp/hashes -D UPDATE=ON \
#         -P tests/scene_hashes.cmake
#
# The hashes belong to one platform: x86-64 with Debian's compiler and C
# library (std::sin and std::exp may round differently elsewhere). A scene
# that exits 1 or 2 fails the test; an `Expect` failure (exit 3, the
# assignments' starters) does not, since its trajectory is still hashed. In a
# students' copy, which has no lectures/instructors/, the scenes listed there
# are skipped.
#
#   cmake -D STEPWISE=<stepwise> -D SOURCE_DIR=<repo> -D SCRATCH_DIR=<dir> [-D UPDATE=ON] -P scene_hashes.cmake
cmake_minimum_required(VERSION 3.20)

foreach(required STEPWISE SOURCE_DIR SCRATCH_DIR)
  if(NOT DEFINED ${required})
    message(FATAL_ERROR "scene-hashes: -D ${required}=… is required (see the header of tests/scene_hashes.cmake)")
  endif()
endforeach()
get_filename_component(SOURCE_DIR "${SOURCE_DIR}" ABSOLUTE)
get_filename_component(STEPWISE "${STEPWISE}" ABSOLUTE)
set(list_file "${SOURCE_DIR}/tests/data/scene_hashes.txt")

file(GLOB_RECURSE scenes RELATIVE "${SOURCE_DIR}" "${SOURCE_DIR}/config/*.scene" "${SOURCE_DIR}/lectures/*.scene")
list(SORT scenes)
if(NOT scenes)
  message(FATAL_ERROR "scene-hashes: no scene found below ${SOURCE_DIR}/config or lectures")
endif()

# The list: "<sha256>  <scene path>" per line.
set(expected_scenes "")
if(NOT UPDATE)
  if(NOT EXISTS "${list_file}")
    message(FATAL_ERROR "scene-hashes: ${list_file} is missing; write it with -D UPDATE=ON")
  endif()
  file(STRINGS "${list_file}" lines REGEX "^[0-9a-f]+  ")
  foreach(line IN LISTS lines)
    string(REGEX MATCH "^([0-9a-f]+)  (.+)$" _ "${line}")
    string(MAKE_C_IDENTIFIER "${CMAKE_MATCH_2}" key)
    set(expected_${key} "${CMAKE_MATCH_1}")
    list(APPEND expected_scenes "${CMAKE_MATCH_2}")
  endforeach()
endif()

file(MAKE_DIRECTORY "${SCRATCH_DIR}")
set(csv "${SCRATCH_DIR}/trajectory.csv")
set(report "")
set(failures 0)
set(written "# SHA-256 of each shipped scene's trajectory (stepwise run SCENE --csv FILE), written by\n")
string(APPEND written "# tests/scene_hashes.cmake with -D UPDATE=ON. The test \"scene-hashes\" compares against it.\n")
foreach(scene IN LISTS scenes)
  file(REMOVE "${csv}")
  execute_process(COMMAND "${STEPWISE}" run "${scene}" --csv "${csv}"
                  WORKING_DIRECTORY "${SOURCE_DIR}" RESULT_VARIABLE exit_code OUTPUT_QUIET ERROR_VARIABLE errors)
  if(NOT (exit_code EQUAL 0 OR exit_code EQUAL 3) OR NOT EXISTS "${csv}")
    string(APPEND report "  ${scene}: stepwise run exited ${exit_code}: ${errors}\n")
    math(EXPR failures "${failures} + 1")
    continue()
  endif()
  file(SHA256 "${csv}" hash)
  string(APPEND written "${hash}  ${scene}\n")
  string(MAKE_C_IDENTIFIER "${scene}" key)
  if(UPDATE)
    continue()
  endif()
  list(REMOVE_ITEM expected_scenes "${scene}")
  if(NOT DEFINED expected_${key})
    string(APPEND report "  ${scene}: not in the list (a new scene? write the list again with -D UPDATE=ON)\n")
    math(EXPR failures "${failures} + 1")
  elseif(NOT hash STREQUAL expected_${key})
    string(APPEND report "  ${scene}: trajectory changed\n      listed ${expected_${key}}\n      now    ${hash}\n")
    math(EXPR failures "${failures} + 1")
  endif()
endforeach()
file(REMOVE "${csv}")
# A students' copy (scripts/student-kit.sh) has no lectures/instructors/: its scenes are not
# missing there, only held back, so they are skipped rather than failed.
set(held_back 0)
foreach(gone IN LISTS expected_scenes)
  if(gone MATCHES "^lectures/instructors/" AND NOT IS_DIRECTORY "${SOURCE_DIR}/lectures/instructors")
    math(EXPR held_back "${held_back} + 1")
    continue()
  endif()
  string(APPEND report "  ${gone}: listed, but no such scene any more (write the list again with -D UPDATE=ON)\n")
  math(EXPR failures "${failures} + 1")
endforeach()
if(held_back GREATER 0)
  message(STATUS "scene-hashes: ${held_back} listed scenes of lectures/instructors/ skipped: a students' copy has none")
endif()

list(LENGTH scenes count)
if(UPDATE)
  if(failures GREATER 0)
    message(FATAL_ERROR "scene-hashes: not written, ${failures} scene(s) did not run:\n${report}")
  endif()
  file(WRITE "${list_file}" "${written}")
  message(STATUS "scene-hashes: wrote ${count} hashes to ${list_file}")
elseif(failures GREATER 0)
  message(FATAL_ERROR "scene-hashes: ${failures} of ${count} scenes differ from tests/data/scene_hashes.txt:\n${report}"
                      "If the physics was meant to change, write the list again (-D UPDATE=ON, header of "
                      "tests/scene_hashes.cmake) in the same commit and say why in its message.")
else()
  message(STATUS "scene-hashes: all ${count} scenes compute the trajectories listed")
endif()
