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
# Debian's ROS sets no ROS_ROOT, but roslib.manifest (roswtf's package checks, run from a package
# directory) reads os.environ['ROS_ROOT'] unguarded and roswtf wants an existing directory named
# "ros": /etc/ros is Debian's ROS configuration directory (ROS_ETC_DIR) and holds no packages.
export ROS_ROOT="${ROS_ROOT:-/etc/ros}"
# The ROS-free programs (k40t, k40t_sim, skyport_sim, k40t_video_sim) by their bare names, as the
# docs use them.
export PATH="$PATH:$K40T_BUILD/core/bin"
export ROS_HOME="${ROS_HOME:-$K40T_BUILD/ros_home}"
export ROSCONSOLE_FORMAT='[${severity}] [${time}] ${node}: ${message}'
