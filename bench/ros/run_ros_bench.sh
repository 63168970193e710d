#!/usr/bin/env bash
# End-to-end figures of the ROS driver (printed, not asserted):
#   1. latency: byte written on the pty -> joint_states in a subscriber of another process
#      (tcp_nodelay) and in a nodelet of the same manager: p50/p99 (target p99 <= 1 ms)
#   2. rtt: set_palette service round trip against the simulator, beside the 115200-baud wire
#      time (target p99 <= wire + 2 ms)
#   3. resources: CPU, RSS and threads of the driver at full telemetry over BENCH_SECONDS
#      (default 60; target <= 1 % of a core and <= 30 MB), and the CPU of each named thread
#   4. skyport: SKYPORT bridge getter ACK latency while a pod call is blocked 2 s (target p99 <=
#      20 ms)
#   5. bag: `k40t bag` decoding a synthetic hour of full-rate pod traffic (target < 10 s)
# Usage: run_ros_bench.sh [latency] [rtt] [resources] [skyport] [bag]   (default: all five)
# Runs on its own ROS master port. Expects a build (scripts/build.sh ros).
set -o pipefail
source "$(dirname "$0")/../../scripts/ros_env.sh"
port="${BENCH_ROS_PORT:-11911}"
export ROS_MASTER_URI="http://127.0.0.1:$port"
out="$K40T_BUILD/bench-ros"
mkdir -p "$out"
rm -f "$out/latency.txt"
seconds="${BENCH_SECONDS:-60}"
sections=" ${*:-latency rtt resources skyport bag} "
wanted() { [[ "$sections" == *" $1 "* ]]; }

launch() {  # launch FILE ARGS...: roslaunch in the background on our port; sets launch_pid
  roslaunch -p "$port" "$@" > "$out/$(basename "$1" .launch).log" 2>&1 &
  launch_pid=$!
}
stop() { kill -INT "$launch_pid" 2>/dev/null; wait "$launch_pid" 2>/dev/null; }

# Tail latencies follow the machine's load: print it beside them.
echo "== load average at the start: $(cut -d' ' -f1-3 /proc/loadavg) on $(nproc) cores"
if wanted latency; then
echo "== latency: byte on the pty -> joint_states"
launch "$K40T_ROOT/bench/ros/latency.launch" in_manager:=false link:=/tmp/k40t_bench_pty_$$ output:="$out/latency.txt"
wait "$launch_pid"
launch "$K40T_ROOT/bench/ros/latency.launch" in_manager:=true link:=/tmp/k40t_bench_pty_$$ output:="$out/latency.txt"
for _ in $(seq 1 600); do [ "$(wc -l < "$out/latency.txt" 2>/dev/null || echo 0)" -ge 2 ] && break; sleep 0.1; done
stop
cat "$out/latency.txt" 2>/dev/null || echo "no latency result (see $out/latency.log)"
fi

if wanted rtt; then
echo "== service round trip"
launch "$K40T_ROOT/bench/ros/service_rtt.launch" link:=/tmp/k40t_bench_rtt_$$
wait "$launch_pid"
grep -A1 "round trip" "$out/service_rtt.log" || echo "no round-trip result (see $out/service_rtt.log)"
fi

if wanted resources; then
echo "== driver CPU and RSS over ${seconds} s at full telemetry"
launch "$K40T_ROOT/launch/sim.launch" sim_link:=/tmp/k40t_bench_res_$$
/usr/bin/python3 "$K40T_ROOT/bench/ros/driver_resources.py" --seconds "$seconds" --node /k40t/driver
stop
fi

if wanted skyport; then
echo "== SKYPORT getter ACK latency while a pod call is blocked"
rosrun k40t_driver k40t_skyport_getter_latency 10
fi

if wanted bag; then
echo "== k40t bag: decoding a synthetic hour of full-rate pod traffic"
rosrun k40t_driver k40t_bag_decode_bench 3600 "$out"
fi
