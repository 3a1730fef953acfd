#!/usr/bin/env bash
# Installs the Debian packages Stepwise needs to build, test and document itself.
#
#   scripts/setup.sh                  safe to run any number of times
#   scripts/setup.sh --with-bullet    also Bullet 3, for `stepwise-bench bullet` (or STEPWISE_WITH_BULLET=1)
#
# Every package present: prints one line and exits 0.
# Some missing, running as root: installs them with apt-get.
# Some missing, not root: prints the exact `sudo apt-get install …` command and exits 1.
set -euo pipefail

# What each package is for:
#   cmake, ninja-build, g++   the build (CMake presets use the Ninja generator)
#   libglm-dev                vectors, matrices and quaternions (find_package(glm))
#   freeglut3-dev             OpenGL and GLUT headers and libraries (the viewer, `stepwise view`;
#                             it brings Mesa's software renderer along)
#   catch2                    the unit tests (Catch2 v2, find_package(Catch2))
#   doxygen                   the API reference (`docs` target)
#   xvfb, xauth               a virtual X display (xvfb-run) for the viewer's screenshot tests
#                             and for `stepwise view --screenshot` on a machine without a screen
#   xdotool                   moves the mouse and presses keys in that display, so the viewer's
#                             picking test drives the real window (tests/test_viewer.cpp)
#   gnuplot-nox               the plots of docs/benchmarks.md (scripts/bench.sh draws them from
#                             stepwise-bench's CSV); -nox: PNG and SVG output without X11
#   gdb                       the lectures' step-through sessions (lectures/gdb/, with Python for
#                             stepwise.py's break-at), and the [gdb] tests that run them
#   clang-14, libfuzzer-14-dev the fuzzers of tests/fuzz/ (scripts/fuzz.sh; README, Fuzzing)
#   libqhull-dev              qhull's reentrant C library, libqhull_r: the convex hull of a
#                             Shape=Hull body's points (src/objects/convex_hull.cpp)
#   libtinyobjloader-dev      reads Wavefront OBJ models, File=model.obj (src/config/obj_file.cpp)
#   dpkg-dev                  dpkg-shlibdeps, which finds the libraries the program loads for the
#                             .deb `cpack` makes (cmake/install.cmake; the test install-deb)
packages=(cmake ninja-build g++ libglm-dev libqhull-dev libtinyobjloader-dev freeglut3-dev catch2 doxygen xvfb xauth xdotool gnuplot-nox gdb dpkg-dev clang-14 libfuzzer-14-dev)

# Only when asked (CI does not need them):
#   libbullet-dev, pkg-config   Bullet 3, the engine `stepwise-bench bullet` compares Stepwise with
#                               (configure with -DSTEPWISE_WITH_BULLET=ON; CMake finds it with pkg-config)
for arg in "$@"; do
    case $arg in
        --with-bullet) STEPWISE_WITH_BULLET=1 ;;
        *) echo "setup: unknown option '$arg' (only --with-bullet)" >&2; exit 2 ;;
    esac
done
if [[ ${STEPWISE_WITH_BULLET:-0} == 1 ]]; then
    packages+=(libbullet-dev pkg-config)
fi

if ! command -v dpkg-query >/dev/null 2>&1; then
    echo "setup: dpkg-query not found: this script installs packages on Debian/Ubuntu only." >&2
    echo "setup: install these (or your system's equivalents) yourself: ${packages[*]}" >&2
    exit 1
fi

missing=()
for pkg in "${packages[@]}"; do
    status=$(dpkg-query -W -f='${Status}' "$pkg" 2>/dev/null || true)
    if [[ "$status" != "install ok installed" ]]; then
        missing+=("$pkg")
    fi
done

if [[ ${#missing[@]} -eq 0 ]]; then
    echo "setup: all packages present"
    exit 0
fi

echo "setup: missing packages: ${missing[*]}"
if [[ $(id -u) -ne 0 ]]; then
    echo "setup: not root; install them with:" >&2
    echo "  sudo apt-get update && sudo apt-get install -y --no-install-recommends ${missing[*]}" >&2
    exit 1
fi

export DEBIAN_FRONTEND=noninteractive
# Wait for another apt/dpkg (e.g. unattended-upgrades) instead of failing at once.
apt_opts=(-q -o DPkg::Lock::Timeout=300)
apt-get "${apt_opts[@]}" update
apt-get "${apt_opts[@]}" install -y --no-install-recommends "${missing[@]}"
echo "setup: installed ${missing[*]}"
