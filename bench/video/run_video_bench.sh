#!/usr/bin/env bash
# Video latency, backlog and CPU, printed (not asserted): the simulated stream (k40t_video_sim,
# frames stamped at render) into the video nodelet and a probe nodelet in the same manager
# (bench/video/video_latency_probe.cpp). For each stream size (1920x1080 visible, 640x512 thermal)
# two configurations run side by side on the same stream for BENCH_SECONDS (default 60):
#   pair 1: the driver's configuration (GStreamer, low latency) and OpenCV's default settings
#           (VideoCapture(url): the FFmpeg back-end with no options in this OpenCV build);
#   pair 2: the other back-end tuned (FFmpeg, low latency) and the GStreamer back-end's defaults.
# Each configuration has its own nodelet manager, so its CPU is the manager process's. The
# simulator's CPU (render + x264 encode, shared by both) is printed too.
# Runs on its own ROS master port. Expects a build (scripts/build.sh ros).
set -o pipefail
source "$(dirname "$0")/../../scripts/ros_env.sh"
port="${BENCH_ROS_PORT:-11912}"
export ROS_MASTER_URI="http://127.0.0.1:$port"
seconds="${BENCH_SECONDS:-60}"
out="$K40T_BUILD/bench-video"
mkdir -p "$out"
results="$out/results.txt"
: > "$results"
sim="$K40T_DEVEL/lib/k40t_driver/k40t_video_sim"

cpu_ticks() { awk '{print $14 + $15}' "/proc/$1/stat" 2>/dev/null || echo 0; }

roscore -p "$port" > "$out/roscore.log" 2>&1 &
core_pid=$!
trap 'kill -INT $core_pid 2>/dev/null; wait $core_pid 2>/dev/null' EXIT
sleep 3

run_pair() {  # run_pair TITLE MODE SIM_PORT "label backend low_latency pts" "label backend low_latency pts"
  local title="$1" mode="$2" sim_port="$3"
  echo "== $title ($seconds s)" | tee -a "$results"
  "$sim" --port "$sim_port" --mode "$mode" --gimbal 0,-4 --sweep 2 > "$out/sim-$sim_port.log" 2>&1 &
  local sim_pid=$!
  sleep 1
  local pids=()
  for config in "$4" "$5"; do
    read -r label backend low_latency pts <<< "$config"
    roslaunch -p "$port" "$K40T_ROOT/bench/video/video_stream.launch" label:="$label" \
      url:="rtsp://127.0.0.1:$sim_port/live/single" backend:="$backend" low_latency:="$low_latency" \
      use_presentation_time:="${pts:-false}" \
      duration:="$seconds" output:="$results" > "$out/$label.log" 2>&1 &
    pids+=($!)
  done
  local start_ticks end_ticks
  sleep 5  # the probes' warm-up
  start_ticks=$(cpu_ticks "$sim_pid")
  local expected=$(( $(grep -c . "$results") + 2 ))
  for _ in $(seq 1 $(( (seconds + 60) * 10 ))); do
    [ "$(grep -c . "$results")" -ge "$expected" ] && break
    sleep 0.1
  done
  end_ticks=$(cpu_ticks "$sim_pid")
  awk -v t=$((end_ticks - start_ticks)) -v hz="$(getconf CLK_TCK)" -v s="$seconds" \
    'BEGIN { printf "simulator (render + x264, both streams share it): cpu %.1f%%\n", 100 * t / hz / s }' \
    | tee -a "$results"
  for pid in "${pids[@]}"; do kill -INT "$pid" 2>/dev/null; done
  for pid in "${pids[@]}"; do wait "$pid" 2>/dev/null; done
  kill "$sim_pid"; wait "$sim_pid" 2>/dev/null
}

# Stamps are read() times (no latency estimate, no presentation times) so that the probe can split
# render -> decoded frame from what the nodelet adds; the last pair compares the stamps of the
# driver's configuration with presentation times (the default) against reception times.
run_pair "1920x1080 @ 30 fps: chosen vs OpenCV defaults" 5 18701 \
  "gst_low_latency_1080 gstreamer true" "opencv_defaults_1080 ffmpeg false"
run_pair "640x512 @ 30 fps: chosen vs OpenCV defaults" 0 18702 \
  "gst_low_latency_512 gstreamer true" "opencv_defaults_512 ffmpeg false"
run_pair "1920x1080 @ 30 fps: other back-end tuned vs GStreamer defaults" 5 18703 \
  "ffmpeg_low_latency_1080 ffmpeg true" "gst_defaults_1080 gstreamer false"
run_pair "640x512 @ 30 fps: other back-end tuned vs GStreamer defaults" 0 18704 \
  "ffmpeg_low_latency_512 ffmpeg true" "gst_defaults_512 gstreamer false"

run_pair "1920x1080 @ 30 fps: stamps from presentation times vs reception times" 5 18705 \
  "gst_stamps_pts_1080 gstreamer true true" "gst_stamps_read_1080 gstreamer true false"

echo
echo "results (also in $results):"
cat "$results"
