#!/usr/bin/env bash
# Installs what this package needs from Debian 12's own packages, and nothing if all is there.
# Idempotent: `apt-get update` and `apt-get install` run only when a package is missing.
set -euo pipefail

packages=(
  build-essential cmake g++ make pkg-config python3
  libgtest-dev libgmock-dev libbenchmark-dev clang libclang-rt-14-dev libboost-dev
  catkin ros-base-dev python3-rostest rosbash python3-rosbag python3-roslaunch
  libnodeletlib-tools libnodelet-dev pluginlib-dev
  libtf2-ros-dev libimage-transport-dev image-transport-tools libcamera-info-manager-dev
  libdiagnostic-updater-dev libopencv-dev python3-dynamic-reconfigure
  libdynamic-reconfigure-config-init-mutex-dev ros-robot-state-publisher
  ros-std-srvs libstd-srvs-dev ros-sensor-msgs libsensor-msgs-dev ros-nav-msgs libnav-msgs-dev
  python3-sensor-msgs python3-diagnostic-msgs python3-std-srvs python3-nodelet python3-nav-msgs
  python3-tf2-ros python3-tf2-msgs libdiagnostic-aggregator-dev libdiagnostic-aggregator-tools
  socat libssl-dev ccache rviz xvfb
  librviz-dev qtbase5-dev
  libactionlib-dev python3-actionlib libactionlib-msgs-dev python3-actionlib-msgs ros-actionlib-msgs
  libgstrtspserver-1.0-dev libgstreamer1.0-dev libgstreamer-plugins-base1.0-dev
  gstreamer1.0-plugins-good gstreamer1.0-plugins-bad gstreamer1.0-plugins-ugly gstreamer1.0-libav
  gstreamer1.0-rtsp gstreamer1.0-tools gstreamer1.0-plugins-base-apps
  libgeographiclib-dev libproj-dev proj-data
  librosbag-storage-dev libyaml-cpp-dev
  libvisualization-msgs-dev python3-visualization-msgs
  catkin-lint
)

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install_deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install_deps: installing ${missing[*]}"
SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" < /dev/null
