# The lectures' figures are drawn by scripts/figures.sh, none by hand (issue #31). This runs the
# script into a scratch folder with the programs of this build and checks that
#   - it succeeds, and makes exactly the images of lectures/images/: no more, no fewer;
#   - each image it makes is a PNG of the same width and height as the committed one;
#   - each committed image is under LIMIT bytes (they are committed, so they stay small).
# A few seconds in Release. When it fails because an image is new or gone, run scripts/figures.sh
# and commit lectures/images/ with the change.
#
#   cmake -D SOURCE_DIR=<repo> -D BUILD_DIR=<build> -D SCRATCH_DIR=<dir> -D LIMIT=100000 -P tests/figures_check.cmake
cmake_minimum_required(VERSION 3.20)  # IN_LIST, and the policies of the project
foreach(variable SOURCE_DIR BUILD_DIR SCRATCH_DIR LIMIT)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "usage: cmake -D SOURCE_DIR=<repo> -D BUILD_DIR=<build> -D SCRATCH_DIR=<dir> -D LIMIT=<bytes> "
                        "-P figures_check.cmake")
  endif()
endforeach()

file(REMOVE_RECURSE "${SCRATCH_DIR}")
file(MAKE_DIRECTORY "${SCRATCH_DIR}")
execute_process(
  COMMAND bash "${SOURCE_DIR}/scripts/figures.sh" --no-build --build-dir "${BUILD_DIR}" --out "${SCRATCH_DIR}"
  RESULT_VARIABLE status OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "scripts/figures.sh failed (${status}):\n${output}\n${errors}")
endif()

set(committed_dir "${SOURCE_DIR}/lectures/images")
file(GLOB made RELATIVE "${SCRATCH_DIR}" "${SCRATCH_DIR}/*")
file(GLOB committed RELATIVE "${committed_dir}" "${committed_dir}/*")
list(SORT made)
list(SORT committed)
set(problems "")
foreach(name IN LISTS committed)
  if(NOT name IN_LIST made)
    list(APPEND problems "lectures/images/${name} is not made by scripts/figures.sh: a figure drawn by hand, or one the script no longer draws")
  endif()
endforeach()
foreach(name IN LISTS made)
  if(NOT name IN_LIST committed)
    list(APPEND problems "scripts/figures.sh makes ${name}, which lectures/images/ does not hold: run the script and commit it")
  endif()
endforeach()

# The PNG signature, the IHDR chunk, then its width and height (big-endian), as hex.
function(png_size path out)
  file(READ "${path}" head LIMIT 24 HEX)
  string(SUBSTRING "${head}" 0 16 signature)
  string(SUBSTRING "${head}" 24 8 chunk)
  if(NOT signature STREQUAL "89504e470d0a1a0a" OR NOT chunk STREQUAL "49484452")
    set(${out} "not a PNG" PARENT_SCOPE)
    return()
  endif()
  string(SUBSTRING "${head}" 32 8 width)
  string(SUBSTRING "${head}" 40 8 height)
  math(EXPR width "0x${width}")
  math(EXPR height "0x${height}")
  set(${out} "${width}x${height}" PARENT_SCOPE)
endfunction()

foreach(name IN LISTS committed)
  if(NOT name IN_LIST made)
    continue()
  endif()
  png_size("${committed_dir}/${name}" committed_size)
  png_size("${SCRATCH_DIR}/${name}" made_size)
  if(NOT committed_size STREQUAL made_size)
    list(APPEND problems "lectures/images/${name} is ${committed_size}, scripts/figures.sh draws it ${made_size}: run the script and commit it")
  endif()
  file(SIZE "${committed_dir}/${name}" bytes)
  if(bytes GREATER LIMIT)
    list(APPEND problems "lectures/images/${name} is ${bytes} bytes, over the limit of ${LIMIT}: draw it smaller")
  endif()
endforeach()

list(LENGTH committed count)
if(count EQUAL 0)
  list(APPEND problems "lectures/images/ holds no image at all")
endif()
if(problems)
  string(REPLACE ";" "\n  " text "${problems}")
  message(FATAL_ERROR "The lectures' figures:\n  ${text}")
endif()
message(STATUS "figures: scripts/figures.sh makes all ${count} images of lectures/images/, each at its committed size")
