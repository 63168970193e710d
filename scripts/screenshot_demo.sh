#!/usr/bin/env bash
# Regenerates docs/images/demo_rviz.png, the README's picture of the demo in rviz: the simulated
# pod and driver with video (demo.launch rviz:=true) on a virtual X display, the gimbal turned
# towards the hot object, iron-red palette, split screen (visible and thermal side by side), a
# laser measurement, and the pod's control panel (PodPanel, docs/panel.md) showing all of it.
# Needs a ROS build (rviz and xvfb come with scripts/install_deps.sh).
set -o pipefail
source "$(dirname "$0")/ros_env.sh"
port="${SCREENSHOT_ROS_PORT:-11913}"
export ROS_MASTER_URI="http://127.0.0.1:$port"
export DISPLAY="${SCREENSHOT_DISPLAY:-:99}"
out="${1:-$K40T_ROOT/docs/images/demo_rviz.png}"
log="$K40T_BUILD/screenshot"
mkdir -p "$log" "$(dirname "$out")"

Xvfb "$DISPLAY" -screen 0 1600x1000x24 > "$log/xvfb.log" 2>&1 &
xvfb_pid=$!
roslaunch -p "$port" k40t_driver demo.launch rviz:=true sim_link:=/tmp/k40t_screenshot_pod \
  > "$log/demo.log" 2>&1 &
launch_pid=$!
trap 'kill -INT $launch_pid 2>/dev/null; wait $launch_pid 2>/dev/null; kill $xvfb_pid 2>/dev/null' EXIT

for _ in $(seq 1 100); do rostopic list > /dev/null 2>&1 && break; sleep 0.2; done  # the master
# The settings read on connect first: a change made while that read is under way is overwritten in
# the driver's published configuration by the values read (the pod itself keeps the change).
rosservice call --wait /k40t/read_settings > /dev/null
rosservice call /k40t/set_palette "palette: 5" > /dev/null
rosservice call /k40t/gimbal/set_angle "{pitch: 0.33, yaw: -0.245}" > /dev/null  # the hot object
rosrun dynamic_reconfigure dynparam set /k40t/driver image_mode 7
sleep 3  # the gimbal there, so that the laser ranges the hot object
rosservice call /k40t/laser/measure > /dev/null
sleep 5  # rviz up, the split screen streaming
gst-launch-1.0 -q ximagesrc display-name="$DISPLAY" num-buffers=1 use-damage=false ! videoconvert \
  ! pngenc ! filesink location="$out"
echo "wrote $out"
