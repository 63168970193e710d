# Sourced by the scripts: a PATH whose python3 is Debian's (catkin's generators need the ROS
# Python modules, which a pyenv interpreter earlier on PATH does not have), and build locations.
export PATH="/usr/bin:/bin:/usr/sbin:/sbin:${PATH}"
K40T_ROOT="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
K40T_BUILD="${K40T_ROOT}/build"
export K40T_ROOT K40T_BUILD
JOBS="${JOBS:-$(nproc)}"
