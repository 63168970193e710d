#!/usr/bin/env bash
# Installs what is missing, builds, runs every test tier, and ends with one line
# "N passed, N failed, N skipped" (non-zero exit on any failure):
#   1. unit    gtest of the ROS-free core (build/core/bin/k40t_unit_tests)
#   2. fuzz    each libFuzzer target for a few seconds (scripts/fuzz.sh)
#   3. launch  roslaunch checks of every launch file (test/launch/check_launch_files.py)
#   4. ros     every rostest under test/ros/*.test, against the simulated pod
# Environment: K40T_SKIP_INSTALL=1 skips the apt step; K40T_TIERS="unit ros" picks tiers.
set -uo pipefail
source "$(dirname "$0")/env.sh"
cd "$K40T_ROOT"

[ "${K40T_SKIP_INSTALL:-0}" = 1 ] || "$K40T_ROOT/scripts/install_deps.sh" || exit 1
"$K40T_ROOT/scripts/build.sh" all || { echo "0 passed, 1 failed"; exit 1; }

tiers="${K40T_TIERS:-unit fuzz launch ros}"
results="$K40T_BUILD/test-results"
rm -rf "$results"
mkdir -p "$results"
failed_steps=()

has_tier() { [[ " $tiers " == *" $1 "* ]]; }

if has_tier unit; then
  echo "== unit tests"
  "$K40T_BUILD/core/bin/k40t_unit_tests" --gtest_output="xml:$results/unit/k40t_unit_tests.xml" \
    > "$results/unit.log" 2>&1
  rc=$?
  tail -n 3 "$results/unit.log"
  [ -f "$results/unit/k40t_unit_tests.xml" ] || failed_steps+=("unit tests (exit $rc, see $results/unit.log)")
fi

if has_tier fuzz && [ -x "$K40T_ROOT/scripts/fuzz.sh" ]; then
  echo "== fuzz (short runs)"
  "$K40T_ROOT/scripts/fuzz.sh" --seconds "${K40T_FUZZ_SECONDS:-4}" --junit "$results/fuzz" \
    || [ -d "$results/fuzz" ] || failed_steps+=("fuzz")
fi

if has_tier launch && [ -f "$K40T_ROOT/test/launch/check_launch_files.py" ]; then
  echo "== launch file checks"
  (source "$K40T_ROOT/scripts/ros_env.sh" && /usr/bin/python3 "$K40T_ROOT/test/launch/check_launch_files.py" \
     --junit "$results/launch/launch_files.xml") || [ -f "$results/launch/launch_files.xml" ] \
     || failed_steps+=("launch checks")
fi

if has_tier ros; then
  shopt -s nullglob
  tests=("$K40T_ROOT"/test/ros/*.test)
  if [ ${#tests[@]} -gt 0 ]; then
    echo "== rostest (${#tests[@]} files)"
    for t in "${tests[@]}"; do
      name="$(basename "$t" .test)"
      echo "-- $name"
      # One results directory per .test file: rostest reuses file names across runs. No --text:
      # with it rostest writes no JUnit XML for the Python test nodes.
      (source "$K40T_ROOT/scripts/ros_env.sh" && export ROS_TEST_RESULTS_DIR="$results/ros/$name" && \
        timeout 600 rostest k40t_driver "$(basename "$t")" > "$results/ros-$name.log" 2>&1)
      rc=$?
      grep -E "^\s*(\* RESULT|\* TESTS|\* ERRORS|\* FAILURES)" "$results/ros-$name.log" | head -5
      # A non-zero exit must show up as a failure even when no XML recorded one (a crashed node,
      # a timeout, a test that never started).
      if [ $rc -ne 0 ] && ! grep -rqsE "<(failure|error)" "$results/ros/$name" 2>/dev/null; then
        failed_steps+=("rostest $name (exit $rc, see $results/ros-$name.log)")
      fi
    done
  fi
fi

args=()
for s in "${failed_steps[@]}"; do args+=(--failed-step "$s"); done
/usr/bin/python3 "$K40T_ROOT/scripts/summarize_results.py" "$results" "${args[@]}"
