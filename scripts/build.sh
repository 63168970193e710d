#!/usr/bin/env bash
# Builds twice, each source compiled once:
#   build/core  plain CMake with K40T_WITH_ROS=OFF: the ROS-free layers, tools, simulators, unit
#               tests and benchmarks, compiled with no ROS include path (the proof that the core
#               needs no ROS);
#   build/ros   the catkin package (nodelets, messages, rostests), devel space in devel/; it links the
#               libraries and runs the programs of build/core (K40T_CORE_BUILD_DIR) instead of
#               compiling them again, so `ros` builds `core` first.
# Usage: scripts/build.sh [core|ros|all]   (default all)
set -euo pipefail
source "$(dirname "$0")/env.sh"
what="${1:-all}"
# Optimised like RelWithDebInfo (-O2) but without debug information, which costs about a third of
# the compile time; K40T_DEBUG_INFO=1 keeps it (for gdb).
if [ "${K40T_DEBUG_INFO:-0}" = 1 ]; then
  build_type=(-DCMAKE_BUILD_TYPE=RelWithDebInfo)
else
  build_type=(-DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O2 -DNDEBUG")
fi
mkdir -p "$K40T_BUILD"
if [ "$what" = core ] || [ "$what" = ros ] || [ "$what" = all ]; then
  cmake -S "$K40T_ROOT" -B "$K40T_BUILD/core" "${K40T_CMAKE_LAUNCHER[@]}" "${build_type[@]}" -DK40T_WITH_ROS=OFF -DK40T_BUILD_BENCH=ON > "$K40T_BUILD/core-configure.log" 2>&1 \
    || { cat "$K40T_BUILD/core-configure.log"; exit 1; }
  cmake --build "$K40T_BUILD/core" -j "$JOBS"
fi
if [ "$what" = ros ] || [ "$what" = all ]; then
  cmake -S "$K40T_ROOT" -B "$K40T_BUILD/ros" "${K40T_CMAKE_LAUNCHER[@]}" "${build_type[@]}" -DK40T_WITH_ROS=ON -DK40T_CORE_BUILD_DIR="$K40T_BUILD/core" -DPYTHON_EXECUTABLE=/usr/bin/python3 \
    -DCATKIN_DEVEL_PREFIX="$K40T_DEVEL" -DCATKIN_ENABLE_TESTING=ON > "$K40T_BUILD/ros-configure.log" 2>&1 \
    || { cat "$K40T_BUILD/ros-configure.log"; exit 1; }
  cmake --build "$K40T_BUILD/ros" -j "$JOBS"
fi
