# CTest test "install-deb" (label install): `cpack -G DEB` makes a .deb a lab machine can install.
#
#   cmake -D BUILD_DIR=<build> -D SCRATCH_DIR=<dir> -D VERSION=<project version> -D LIBDIR=<lib folder>
#         -D VIEWER=<ON|OFF> -P deb_check.cmake
#
# Packs the build as it is (nothing is compiled again) into SCRATCH_DIR and reads the package back
# with dpkg-deb: its name and version are the project's; it has a maintainer and a description
# (in lines of at most 80 characters); it depends on what the program loads (found by
# dpkg-shlibdeps: the C++ runtime, and freeglut when the viewer is built in) and on GLM's headers
# and qhull's and tinyobjloader's development packages (the static library needs them);
# and it holds the program, the library, the headers, the CMake package and the scenes below /usr.
cmake_minimum_required(VERSION 3.20)

foreach(variable BUILD_DIR SCRATCH_DIR VERSION LIBDIR VIEWER)
  if(NOT DEFINED ${variable})
    message(FATAL_ERROR "deb_check.cmake: give -D ${variable}=…")
  endif()
endforeach()
find_program(DPKG_DEB dpkg-deb)
find_program(DPKG_SHLIBDEPS dpkg-shlibdeps)
if(NOT DPKG_DEB OR NOT DPKG_SHLIBDEPS)
  message(FATAL_ERROR "install-deb: dpkg-deb and dpkg-shlibdeps are needed (Debian package dpkg-dev; scripts/setup.sh installs it)")
endif()

file(REMOVE_RECURSE "${SCRATCH_DIR}")
execute_process(COMMAND cpack --config "${BUILD_DIR}/CPackConfig.cmake" -G DEB -B "${SCRATCH_DIR}"
                RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "install-deb: cpack failed (${result}):\n${output}${errors}")
endif()
file(GLOB debs "${SCRATCH_DIR}/*.deb")
list(LENGTH debs count)
if(NOT count EQUAL 1)
  message(FATAL_ERROR "install-deb: expected one .deb in ${SCRATCH_DIR}, found ${count}:\n${output}${errors}")
endif()
get_filename_component(name "${debs}" NAME)
if(NOT name MATCHES "^stepwise_${VERSION}_[a-z0-9]+\\.deb$")
  message(FATAL_ERROR "install-deb: the package is ${name}, not stepwise_${VERSION}_<architecture>.deb")
endif()

# field(<name> <variable>): the control field <name> of the package.
function(field name variable)
  execute_process(COMMAND "${DPKG_DEB}" --field "${debs}" "${name}" OUTPUT_VARIABLE value RESULT_VARIABLE result
                  OUTPUT_STRIP_TRAILING_WHITESPACE)
  if(NOT result EQUAL 0 OR value STREQUAL "")
    message(FATAL_ERROR "install-deb: ${name} has no ${name} field")
  endif()
  set(${variable} "${value}" PARENT_SCOPE)
endfunction()
field(Package package)
field(Version version)
field(Maintainer maintainer)
field(Description description)
field(Depends depends)
if(NOT package STREQUAL "stepwise" OR NOT version STREQUAL "${VERSION}")
  message(FATAL_ERROR "install-deb: Package ${package}, Version ${version}: expected stepwise ${VERSION}")
endif()
if(NOT maintainer MATCHES "^[^<]+ <[^@>]+@[^>]+>$")
  message(FATAL_ERROR "install-deb: the Maintainer field \"${maintainer}\" is not \"Name <e-mail>\"")
endif()
# Debian's control file: the description's lines (summary, then the long text) fit in 80 columns.
string(REPLACE "\n" ";" description_lines "${description}")
foreach(line IN LISTS description_lines)
  string(LENGTH "${line}" length)
  if(length GREATER 80)
    message(FATAL_ERROR "install-deb: a line of the Description is ${length} characters long, over 80:\n${line}")
  endif()
endforeach()
set(needed libglm-dev libqhull-dev libtinyobjloader-dev libc6 libstdc\\+\\+6)
if(VIEWER)
  list(APPEND needed libglut)
endif()
foreach(dependency IN LISTS needed)
  if(NOT depends MATCHES "(^|, )${dependency}")
    message(FATAL_ERROR "install-deb: Depends does not name ${dependency}: ${depends}")
  endif()
endforeach()

execute_process(COMMAND "${DPKG_DEB}" --contents "${debs}" OUTPUT_VARIABLE contents RESULT_VARIABLE result)
if(NOT result EQUAL 0)
  message(FATAL_ERROR "install-deb: dpkg-deb --contents failed")
endif()
foreach(path usr/bin/stepwise usr/${LIBDIR}/libstepwise_engine.a usr/include/stepwise/world/world.hpp
             usr/${LIBDIR}/cmake/Stepwise/StepwiseConfig.cmake usr/${LIBDIR}/cmake/Stepwise/StepwiseConfigVersion.cmake
             usr/${LIBDIR}/cmake/Stepwise/StepwiseTargets.cmake usr/share/stepwise/config/default.scene)
  string(FIND "${contents}" " ./${path}\n" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "install-deb: ${name} has no /${path}:\n${contents}")
  endif()
endforeach()
file(SIZE "${debs}" size)
math(EXPR kib "${size} / 1024")
message(STATUS "install-deb: ${name}, ${kib} KiB; Depends: ${depends}")
