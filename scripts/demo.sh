#!/usr/bin/env bash
# The demo: the simulated pod and the ROS driver (demo.launch: k40t_sim on a pty, k40t_node,
# robot_state_publisher with the URDF), and live telemetry printed by scripts/k40t_status.py while
# it drives the pod through its services.
#   scripts/demo.sh                  until Ctrl-C
#   DEMO_SECONDS=20 scripts/demo.sh  stops by itself (CI: with CI set, 20 s unless DEMO_SECONDS)
#   DEMO_RVIZ=true scripts/demo.sh   with rviz (needs the rviz package)
# Expects a build (scripts/build.sh ros, which `make demo` runs first).
set -eo pipefail
source "$(dirname "$0")/ros_env.sh"

seconds="${DEMO_SECONDS:-}"
[ -z "$seconds" ] && [ -n "${CI:-}" ] && seconds=20
log_dir="$K40T_BUILD/demo"
mkdir -p "$log_dir"

roslaunch k40t_driver demo.launch rviz:="${DEMO_RVIZ:-false}" sim_link:="/tmp/k40t_demo_pod_$$" \
  > "$log_dir/roslaunch.log" 2>&1 &
launch_pid=$!
cleanup() {
  kill -INT "$launch_pid" 2>/dev/null || true
  wait "$launch_pid" 2>/dev/null || true
}
trap cleanup EXIT

echo "k40t demo: simulated pod + driver (logs: $log_dir/roslaunch.log); Ctrl-C to stop"
for _ in $(seq 1 100); do
  rostopic list 2>/dev/null | grep -q '^/k40t/joint_states$' && break
  kill -0 "$launch_pid" 2>/dev/null || { echo "roslaunch exited:"; tail -n 20 "$log_dir/roslaunch.log"; exit 1; }
  sleep 0.2
done

/usr/bin/python3 "$K40T_ROOT/scripts/k40t_status.py" --tour ${seconds:+--seconds "$seconds"}
