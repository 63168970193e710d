# Sourced after a build: the devel space (devel/, built by build/ros) and this package on ROS_PACKAGE_PATH, so
# rosrun/roslaunch/rostest find k40t_driver without a catkin workspace.
source "$(dirname "${BASH_SOURCE[0]}")/env.sh"
# catkin's setup scripts read unset variables (ROS_DISTRO...): relax nounset while sourcing them.
case $- in *u*) k40t_nounset=1; set +u ;; *) k40t_nounset=0 ;; esac
# shellcheck disable=SC1091
source "$K40T_DEVEL/setup.bash"
[ "$k40t_nounset" = 1 ] && set -u
unset k40t_nounset
export ROS_PACKAGE_PATH="$K40T_ROOT:${ROS_PACKAGE_PATH:-}"
# The ROS-free programs (k40t, k40t_sim, skyport_sim, k40t_video_sim) by their bare names, as the
# docs use them.
export PATH="$PATH:$K40T_BUILD/core/bin"
export ROS_HOME="${ROS_HOME:-$K40T_BUILD/ros_home}"
export ROSCONSOLE_FORMAT='[${severity}] [${time}] ${node}: ${message}'
