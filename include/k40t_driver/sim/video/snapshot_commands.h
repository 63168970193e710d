// A line-oriented control language for what the standalone simulated stream shows (k40t_video_sim
// reads it on stdin; tests and benchmarks write it):
//   mode 0|5|6|7            image mode: thermal, visible, visible, split screen
//   palette 1..20           thermal palette
//   zoom 1..160             telephoto hybrid zoom
//   thermal_zoom 1..8       thermal digital zoom
//   gimbal YAW PITCH        boresight heading and elevation, degrees (pitch -90..90)
//   resolution 1080|720     visible / split-screen stream resolution
// Blank lines and lines starting with '#' are ignored.
#pragma once

#include <string>

#include "k40t_driver/protocol/result.h"
#include "k40t_driver/sim/video/video_snapshot.h"

namespace k40t::sim::video {

// Applies one command to `snapshot`; on error (unknown command, missing or out-of-range value)
// the snapshot is unchanged and the message names the command and the accepted values.
Status apply_command(const std::string& line, VideoSnapshot& snapshot);

}  // namespace k40t::sim::video
