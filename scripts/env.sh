# Sourced by the scripts: a PATH whose python3 is Debian's (catkin's generators need the ROS
# Python modules, which a pyenv interpreter earlier on PATH does not have), and build locations.
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:${PATH}"
K40T_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
K40T_BUILD="${K40T_ROOT}/build"
# The catkin devel space sits beside build/, not in it: rosrun ignores every executable below
# <package>/build/, so `rosrun k40t_driver k40t_sim` would not find a devel space there.
K40T_DEVEL="${K40T_ROOT}/devel"
export K40T_ROOT K40T_BUILD K40T_DEVEL
JOBS="${JOBS:-$(nproc)}"
# ccache (installed by install_deps.sh) makes a second build of unchanged sources nearly free;
# the base directory makes its hits independent of where the clone lives.
K40T_CMAKE_LAUNCHER=()
if command -v ccache >/dev/null 2>&1; then
  K40T_CMAKE_LAUNCHER=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="$K40T_ROOT"
fi
