#!/usr/bin/env bash
# Installs what is missing, builds, runs every test tier, and ends with the line
# "N passed, N failed" (non-zero exit on any failure). Each tier prints its wall time.
#   deps    the dependency check (test/deps/check_deps.py): every Python module, launched node and
#           shell command the package uses comes from a package install_deps.sh installs; and the
#           same check run without one package of the list must fail
#   unit    gtest of the ROS-free core (build/core/bin/k40t_unit_tests)
#   fuzz    each libFuzzer target for a few seconds (scripts/fuzz.sh)
#   launch  roslaunch checks of every launch file (test/launch/check_launch_files.py), what
#           the nodelet libraries link and declare (test/launch/check_nodelet_libraries.py), the
#           package's conventions (test/launch/check_package.py: layers, catkin_lint, README),
#           sim.launch from an install space (test/launch/check_install_space.py), and the launch
#           files started as in the field (test/launch/check_field.py)
#   stop    every nodelet unloaded and every manager and node stopped at random moments
#           (test/stop/clean_stop.py); runs beside the other tiers
#   ros     every rostest under test/ros/*.test against the simulated pod, K40T_ROSTEST_JOBS
#           (default 2) files at a time, longest first
# Environment: K40T_SKIP_INSTALL=1 skips the apt step; K40T_TIERS="unit ros" picks tiers.
set -uo pipefail
source "$(dirname "$0")/env.sh"
cd "$K40T_ROOT"

started=$(date +%s)
tier_start=$started
tier_done() {  # $1 tier name: prints its wall time
  local now
  now=$(date +%s)
  echo "== $1: $((now - tier_start)) s"
  tier_start=$now
}

tiers="${K40T_TIERS:-deps unit fuzz launch stop ros}"
has_tier() { [[ " $tiers " == *" $1 "* ]]; }
results="$K40T_BUILD/test-results"
mkdir -p "$K40T_BUILD"
rm -rf "$results"
mkdir -p "$results"
failed_steps=()

[ "${K40T_SKIP_INSTALL:-0}" = 1 ] || "$K40T_ROOT/scripts/install_deps.sh" || exit 1
tier_done "install"

if has_tier deps; then
  echo "== dependency check"
  /usr/bin/python3 test/deps/check_deps.py --junit "$results/deps/check_deps.xml" \
    > "$results/deps.log" 2>&1 || [ -f "$results/deps/check_deps.xml" ] || failed_steps+=("deps")
  tail -n 1 "$results/deps.log"
  grep '^FAIL' "$results/deps.log"
  # The check must be able to fail: without python3-sensor-msgs (imported by the rostests) it has to.
  if /usr/bin/python3 test/deps/check_deps.py --without python3-sensor-msgs > "$results/deps-without.log" 2>&1 \
     || ! grep -q "python3-sensor-msgs" "$results/deps-without.log"; then
    failed_steps+=("deps: the check passed with python3-sensor-msgs left out of the list")
  fi
  tier_done "deps"
fi

"$K40T_ROOT/scripts/build.sh" all || { echo "0 passed, 1 failed"; exit 1; }
tier_done "build"

# The stop tier mostly waits for processes to start and end: it runs beside the other tiers.
stop_pid=""
field_pid=""
if has_tier stop; then
  echo "== clean-stop test (in the background, log: $results/stop.log)"
  (source "$K40T_ROOT/scripts/ros_env.sh" && timeout 900 /usr/bin/python3 test/stop/clean_stop.py \
     --junit "$results/stop/clean_stop.xml" --logs "$results/stop-logs") > "$results/stop.log" 2>&1 &
  stop_pid=$!
  stop_start=$(date +%s)
fi

if has_tier unit; then
  # gtest shards side by side: most of the time goes to simulated pods and RTSP servers answering
  # in real time (the conformance tests), not to the CPU.
  shards="${K40T_UNIT_SHARDS:-3}"
  echo "== unit tests ($shards shards)"
  unit_pids=()
  for i in $(seq 0 $((shards - 1))); do
    GTEST_TOTAL_SHARDS=$shards GTEST_SHARD_INDEX=$i "$K40T_BUILD/core/bin/k40t_unit_tests" \
      --gtest_output="xml:$results/unit/shard_$i.xml" > "$results/unit-$i.log" 2>&1 &
    unit_pids+=($!)
  done
  for i in "${!unit_pids[@]}"; do
    wait "${unit_pids[$i]}"
    rc=$?
    tail -n 2 "$results/unit-$i.log"
    [ -f "$results/unit/shard_$i.xml" ] || failed_steps+=("unit tests, shard $i (exit $rc, see $results/unit-$i.log)")
  done
  tier_done "unit"
fi

if has_tier fuzz && [ -x "$K40T_ROOT/scripts/fuzz.sh" ]; then
  echo "== fuzz (short runs)"
  "$K40T_ROOT/scripts/fuzz.sh" --seconds "${K40T_FUZZ_SECONDS:-4}" --junit "$results/fuzz" \
    || [ -d "$results/fuzz" ] || failed_steps+=("fuzz")
  tier_done "fuzz"
fi

if has_tier launch && [ -f "$K40T_ROOT/test/launch/check_launch_files.py" ]; then
  echo "== launch file checks"
  (source "$K40T_ROOT/scripts/ros_env.sh" && /usr/bin/python3 "$K40T_ROOT/test/launch/check_launch_files.py" \
     --junit "$results/launch/launch_files.xml") || [ -f "$results/launch/launch_files.xml" ] \
     || failed_steps+=("launch checks")
  /usr/bin/python3 "$K40T_ROOT/test/launch/check_nodelet_libraries.py" \
     --junit "$results/launch/nodelet_libraries.xml" || [ -f "$results/launch/nodelet_libraries.xml" ] \
     || failed_steps+=("nodelet library checks")
  /usr/bin/python3 "$K40T_ROOT/test/launch/check_package.py" --junit "$results/launch/package_checks.xml" \
     || [ -f "$results/launch/package_checks.xml" ] || failed_steps+=("package checks")
  # The build installed into a temporary prefix, then sim.launch from there alone.
  /usr/bin/python3 "$K40T_ROOT/test/launch/check_install_space.py" --junit "$results/launch/install_space.xml" \
     || [ -f "$results/launch/install_space.xml" ] || failed_steps+=("install space checks")
  # That check must be able to fail: with k40t.launch taken out of the install space it has to.
  if /usr/bin/python3 "$K40T_ROOT/test/launch/check_install_space.py" \
       --remove share/k40t_driver/launch/k40t.launch > "$results/install-space-without.log" 2>&1 \
     || ! grep -q "FAIL files: .*" "$results/install-space-without.log" \
     || ! grep -q "share/k40t_driver/launch/k40t.launch" "$results/install-space-without.log"; then
    failed_steps+=("install space: the check passed with k40t.launch removed from the install space")
  fi
  # The launch files as a user starts them: quiet starts, roswtf, the flight recorder cut by
  # SIGKILL and its recovery, replay's clean end. 45-60 s, mostly waiting for the 20 s recording:
  # it runs beside the ros tier, like the stop tier, and is waited for at the end.
  echo "== field checks (in the background, log: $results/launch-field.log)"
  (source "$K40T_ROOT/scripts/ros_env.sh" && timeout 300 /usr/bin/python3 "$K40T_ROOT/test/launch/check_field.py" \
     --junit "$results/launch/field.xml") > "$results/launch-field.log" 2>&1 &
  field_pid=$!
  tier_done "launch"
fi

# One rostest file; its log and results directory are its own (rostest reuses file names).
# No --text: with it rostest writes no JUnit XML for the Python test nodes.
run_rostest() {
  local name
  name="$(basename "$1" .test)"
  (source "$K40T_ROOT/scripts/ros_env.sh" && export ROS_TEST_RESULTS_DIR="$results/ros/$name" && \
    timeout 600 rostest k40t_driver "$(basename "$1")" > "$results/ros-$name.log" 2>&1)
  echo $? > "$results/ros-$name.rc"
}

if has_tier ros; then
  shopt -s nullglob
  # Longest first (the figures of the last run, if any), so the parallel slots end together.
  mapfile -t tests < <(for t in "$K40T_ROOT"/test/ros/*.test; do
    n="$(basename "$t" .test)"; echo "$(cat "$K40T_BUILD/rostest-seconds/$n" 2>/dev/null || echo 999) $t"
  done | sort -rn | cut -d' ' -f2-)
  jobs_max="${K40T_ROSTEST_JOBS:-2}"
  echo "== rostest (${#tests[@]} files, $jobs_max at a time)"
  mkdir -p "$K40T_BUILD/rostest-seconds"
  for t in "${tests[@]}"; do
    while [ "$(jobs -rp | grep -vcE "^(${stop_pid:-none}|${field_pid:-none})$")" -ge "$jobs_max" ]; do sleep 0.2; done
    (s=$(date +%s); run_rostest "$t"; echo $(( $(date +%s) - s )) > "$K40T_BUILD/rostest-seconds/$(basename "$t" .test)") &
  done
  for pid in $(jobs -rp); do [ "$pid" = "${stop_pid:-}" ] || [ "$pid" = "${field_pid:-}" ] || wait "$pid"; done
  for t in "${tests[@]}"; do
    name="$(basename "$t" .test)"
    rc=$(cat "$results/ros-$name.rc" 2>/dev/null || echo 1)
    echo "-- $name ($(cat "$K40T_BUILD/rostest-seconds/$name" 2>/dev/null) s)"
    grep -E "^\s*(\* RESULT|\* TESTS|\* ERRORS|\* FAILURES)" "$results/ros-$name.log" | head -5
    # A non-zero exit must show up as a failure even when no XML recorded one (a crashed node,
    # a timeout, a test that never started).
    if [ "$rc" -ne 0 ] && ! grep -rqsE "<(failure|error)" "$results/ros/$name" 2>/dev/null; then
      failed_steps+=("rostest $name (exit $rc, see $results/ros-$name.log)")
    fi
  done
  tier_done "ros"
fi

if [ -n "$field_pid" ]; then
  wait "$field_pid"
  grep -E "^(FAIL|[0-9]+ field checks)" "$results/launch-field.log"
  [ -f "$results/launch/field.xml" ] || failed_steps+=("field checks (see $results/launch-field.log)")
fi

if [ -n "$stop_pid" ]; then
  wait "$stop_pid"
  tail -n 1 "$results/stop.log"
  grep "FAIL" "$results/stop.log"
  [ -f "$results/stop/clean_stop.xml" ] || failed_steps+=("clean-stop test (see $results/stop.log)")
  echo "== stop: $(( $(date +%s) - stop_start )) s (beside the other tiers)"
fi

echo "== total: $(( $(date +%s) - started )) s"
args=()
for s in "${failed_steps[@]}"; do args+=(--failed-step "$s"); done
/usr/bin/python3 "$K40T_ROOT/scripts/summarize_results.py" "$results" "${args[@]}"
