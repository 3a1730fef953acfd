# Installing Stepwise for a lab (README.md, "Installing for a lab"; docs/instructors.md, "A course's own project").
#
#   cmake --install build/release --prefix PREFIX    into any folder (PREFIX/bin/stepwise, …)
#   cd build/release && cpack -G DEB                 a .deb of the same files, below /usr
#
# What is installed, below the prefix:
#
#   bin/stepwise                          the program
#   lib/libstepwise_engine.a              the engine (no OpenGL, no GLUT)
#   include/stepwise/core/…, …/world/…    its headers, folder by folder as below src/: a user puts
#                                         include/stepwise on the include path and writes
#                                         #include "world/world.hpp", as the engine's own files do
#   share/stepwise/config/*.scene         the scenes; `stepwise run` with no file opens default.scene
#   share/stepwise/config/models/*.obj    the OBJ models the scenes read (File=models/…)
#   lib/cmake/Stepwise/                   the CMake package: find_package(Stepwise) gives the
#                                         target Stepwise::engine
#
# The folders are GNUInstallDirs' (CMAKE_INSTALL_BINDIR, …), so a distribution's own layout applies.
# Everything is found relative to where it was installed, so the installed tree can be moved.
# The viewer (src/viewer/) and the program's commands (src/app/) are part of the program only:
# their headers are not installed.

include(CMakePackageConfigHelpers)

set(STEPWISE_INSTALL_CMAKEDIR "${CMAKE_INSTALL_LIBDIR}/cmake/Stepwise")

install(TARGETS stepwise RUNTIME DESTINATION "${CMAKE_INSTALL_BINDIR}")

# The library and the usage it carries (CMakeLists.txt, stepwise_engine_usage): the headers'
# folder, C++20, GLM, threads, and the definitions STEPWISE_SINGLE_PRECISION and
# STEPWISE_FAST_PATH_BY_DEFAULT when this build was configured with them.
set_target_properties(stepwise_engine PROPERTIES EXPORT_NAME engine)
set_target_properties(stepwise_engine_usage PROPERTIES EXPORT_NAME engine_usage)
install(TARGETS stepwise_engine stepwise_engine_usage EXPORT StepwiseTargets
        ARCHIVE DESTINATION "${CMAKE_INSTALL_LIBDIR}")
install(DIRECTORY "${PROJECT_SOURCE_DIR}/src/" DESTINATION "${CMAKE_INSTALL_INCLUDEDIR}/stepwise"
        FILES_MATCHING PATTERN "*.hpp"
        PATTERN "app" EXCLUDE
        PATTERN "viewer" EXCLUDE)

install(DIRECTORY "${PROJECT_SOURCE_DIR}/config/" DESTINATION "${CMAKE_INSTALL_DATADIR}/stepwise/config"
        FILES_MATCHING PATTERN "*.scene" PATTERN "*.obj")

install(EXPORT StepwiseTargets NAMESPACE Stepwise:: DESTINATION "${STEPWISE_INSTALL_CMAKEDIR}")
configure_package_config_file("${CMAKE_CURRENT_LIST_DIR}/StepwiseConfig.cmake.in"
  "${PROJECT_BINARY_DIR}/StepwiseConfig.cmake" INSTALL_DESTINATION "${STEPWISE_INSTALL_CMAKEDIR}")
# A new minor version may change the engine's interface (the lectures' engine moves on between
# courses): find_package(Stepwise X.Y) accepts X.Y.z only.
write_basic_package_version_file("${PROJECT_BINARY_DIR}/StepwiseConfigVersion.cmake"
  COMPATIBILITY SameMinorVersion)
install(FILES "${PROJECT_BINARY_DIR}/StepwiseConfig.cmake" "${PROJECT_BINARY_DIR}/StepwiseConfigVersion.cmake"
        DESTINATION "${STEPWISE_INSTALL_CMAKEDIR}")

# The .deb for lab machines: `cpack -G DEB` in the build folder writes stepwise_<version>_<arch>.deb.
# One package holds everything above (the program for students who run scenes, the library and
# headers for a course's own project), installed below /usr.
set(STEPWISE_PACKAGE_MAINTAINER "Stepwise maintainers <maintainers@users.noreply.h-seed-65033616.example>"
    CACHE STRING "Maintainer field of the .deb (\"Name <e-mail>\"): whoever builds the package for a lab")
set(CPACK_PACKAGE_NAME "stepwise")
set(CPACK_PACKAGE_VENDOR "Stepwise")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_CONTACT "${STEPWISE_PACKAGE_MAINTAINER}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "3D rigid-body physics engine for teaching")
set(CPACK_GENERATOR "DEB")
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
# The long description, in lines under 80 characters as Debian's control file wants them;
# CPack puts the summary above it and indents each line by one space.
set(CPACK_PACKAGE_DESCRIPTION "Stepwise simulates scenes of spheres, boxes and planes one stage of the step
at a time, for a course on physics engines. This package holds the stepwise
program (run, check, view, grade, trace and plot scenes), the lecture and
reference scenes in /usr/share/stepwise/config, and the engine as a static
library with its headers and a CMake package: a course's own project links it
with find_package(Stepwise) and the target Stepwise::engine.")
# The libraries the program loads (libc, libstdc++, freeglut and OpenGL when the viewer is built
# in) come from dpkg-shlibdeps. The headers include GLM's, and the CMake package looks for it,
# so libglm-dev too; the static library calls qhull and tinyobjloader, whose CMake packages the
# Stepwise package finds, so libqhull-dev and libtinyobjloader-dev; a course's own project also
# needs a C++20 compiler and CMake.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "libglm-dev, libqhull-dev, libtinyobjloader-dev")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "cmake (>= 3.20), g++ (>= 4:12)")
# `stepwise plot` draws with gnuplot, which it runs as a program: without it, plot says how to get it.
set(CPACK_DEBIAN_PACKAGE_SUGGESTS "gnuplot-nox")
include(CPack)
