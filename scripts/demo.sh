#!/usr/bin/env bash
# The main job: until the ROS driver lands, `k40t monitor` on the sample capture in test/data.
set -euo pipefail
source "$(dirname "$0")/env.sh"
exec "$K40T_BUILD/core/bin/k40t" monitor "$K40T_ROOT/test/data/sample_capture.bin"
