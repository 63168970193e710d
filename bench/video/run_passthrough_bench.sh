#!/usr/bin/env bash
# The passthrough video measured, printed (not asserted), for docs/video.md: the simulated stream
# (k40t_video_sim, panning so every frame differs) into k40t_video_node, and one subscriber
# process at a time (bench/video/passthrough_probe.cpp) for BENCH_SECONDS (default 30) each:
#   raw          image_raw (the node decodes, converts, publishes 3 bytes a pixel);
#   passthrough  image_raw/k40t_video only (the node neither decodes nor converts);
#   k40t_video   image_raw through the k40t_video plugin (the node as for passthrough; the
#                probe decodes): its render -> arrival latency against raw's is the plugin's cost.
# For each: messages/s, payload bytes/s, latency from render (frame stamp) to the subscriber, and
# the video node's CPU (% of one core, /proc) and, on a `threads:` line, each of its threads' (run
# time from /proc/PID/task/*/schedstat). Then a bag of image_raw/k40t_video recorded for
# BAG_SECONDS (default 60) with rosbag record, and its size scaled to 10 minutes.
# Streams: 1920x1080 (mode 5) and 640x512 (mode 0) at 30 fps, x264 4 Mbit/s, key frame every 30.
# Runs on its own ROS master port (BENCH_ROS_PORT, default 11913). Expects scripts/build.sh all.
set -o pipefail
source "$(dirname "$0")/../../scripts/ros_env.sh"
port="${BENCH_ROS_PORT:-11913}"
export ROS_MASTER_URI="http://127.0.0.1:$port"
seconds="${BENCH_SECONDS:-30}"
bag_seconds="${BAG_SECONDS:-60}"
out="$K40T_BUILD/bench-passthrough"
mkdir -p "$out"
results="$out/results.txt"
: > "$results"
bin="$K40T_DEVEL/lib/k40t_driver"

cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat" 2>/dev/null || echo 0; }
hz="$(getconf CLK_TCK)"
# Run time of each thread of process $1 in ns (schedstat), "tid name ns" lines, into file $2.
thread_times() {
  for t in /proc/"$1"/task/*; do
    echo "${t##*/} $(tr ' ' '_' < "$t/comm") $(awk '{print $1}' "$t/schedstat" 2>/dev/null || echo 0)"
  done > "$2"
}
# The threads that ran at least 0.02 % of a core between two thread_times files over $3 s.
thread_report() {
  local program='NR == FNR { start[$1] = $3; next } { p = ($3 - ($1 in start ? start[$1] : $3)) / 1e7 / s; if (p >= 0.02) printf " %s=%.2f%%", $2, p } END { print "" }'
  awk -v s="$3" "$program" "$1" "$2"
}

roscore -p "$port" > "$out/roscore.log" 2>&1 &
core_pid=$!
pids=()
cleanup() {
  for p in "${pids[@]}"; do kill -INT "$p" 2>/dev/null; done
  for p in "${pids[@]}"; do wait "$p" 2>/dev/null; done
  kill -INT $core_pid 2>/dev/null; wait $core_pid 2>/dev/null
}
trap cleanup EXIT
sleep 3

measure() {  # measure TITLE MODE
  local title="$1" mode="$2"
  echo "== $title" | tee -a "$results"
  "$bin/k40t_video_sim" --port 0 --mode "$mode" --gimbal 0,-4 --sweep 2 > "$out/sim-$mode.log" 2>&1 &
  local sim_pid=$!
  pids+=("$sim_pid")
  local url=""
  for _ in $(seq 50); do  # its first line: "k40t_video_sim: serving rtsp://..."
    url="$(grep -o 'rtsp://[^ ]*' "$out/sim-$mode.log" | head -1)"
    [ -n "$url" ] && break
    sleep 0.1
  done
  "$bin/k40t_video_node" __name:=video __ns:=/bench _url:="$url" _latency:=0.0 \
    > "$out/video-$mode.log" 2>&1 &
  local video_pid=$!
  pids+=("$video_pid")
  sleep 2
  for kind in raw passthrough k40t_video; do
    local start end
    "$bin/k40t_passthrough_probe" __ns:=/bench __name:="probe_$kind" _kind:="$kind" \
      _seconds:="$seconds" > "$out/probe-$kind-$mode.log" 2>&1 &
    local probe=$!
    sleep 2  # the probe's warm-up
    start=$(cpu_ticks "$video_pid")
    thread_times "$video_pid" "$out/threads-start"
    sleep "$seconds"
    end=$(cpu_ticks "$video_pid")
    thread_times "$video_pid" "$out/threads-end"
    wait "$probe"
    printf '%s | video node cpu %.1f%%\n' "$(tail -1 "$out/probe-$kind-$mode.log")" \
      "$(awk -v t=$((end - start)) -v hz="$hz" -v s="$seconds" 'BEGIN { print 100 * t / hz / s }')" \
      | tee -a "$results"
    echo "  threads:$(thread_report "$out/threads-start" "$out/threads-end" "$seconds")" | tee -a "$results"
  done
  local start end
  start=$(cpu_ticks "$video_pid")
  thread_times "$video_pid" "$out/threads-start"
  sleep "$seconds"
  end=$(cpu_ticks "$video_pid")
  thread_times "$video_pid" "$out/threads-end"
  printf 'no subscriber | video node cpu %.1f%%\n' \
    "$(awk -v t=$((end - start)) -v hz="$hz" -v s="$seconds" 'BEGIN { print 100 * t / hz / s }')" \
    | tee -a "$results"
  echo "  threads:$(thread_report "$out/threads-start" "$out/threads-end" "$seconds")" | tee -a "$results"
  rosbag record -O "$out/passthrough-$mode.bag" --duration="$bag_seconds" /bench/image_raw/k40t_video \
    > "$out/record-$mode.log" 2>&1
  local size
  size=$(stat -c %s "$out/passthrough-$mode.bag")
  awk -v b="$size" -v s="$bag_seconds" 'BEGIN { printf "bag of image_raw/k40t_video: %.1f MB in %d s -> %.0f MB for 10 minutes\n", b / 1e6, s, b / 1e6 * 600 / s }' \
    | tee -a "$results"
  "$bin/k40t_bag" "$out/passthrough-$mode.bag" --video "$out/passthrough-$mode.mp4" \
    2>&1 | tail -1 | tee -a "$results"
  gst-discoverer-1.0 "$out/passthrough-$mode.mp4" | grep -i duration | tee -a "$results"
  kill -INT "$video_pid"; wait "$video_pid" 2>/dev/null
  kill "$sim_pid"; wait "$sim_pid" 2>/dev/null
  pids=()
}

measure "1920x1080 @ 30 fps" 5
measure "640x512 @ 30 fps" 0

echo
echo "results (also in $results):"
cat "$results"
