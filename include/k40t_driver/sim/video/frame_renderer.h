// One frame of the simulated pod's stream, as the image mode selects:
//   thermal (0)          640 x 512, the thermal image;
//   visible (5, 6)       1920 x 1080 (or 1280 x 720 at the 720p stream resolution), telephoto;
//   split screen (7)     1920 x 1080 (1280 x 720): the visible image and the thermal image side
//                        by side as video/stream_view.h's split_layout() places them (the
//                        client decodes the panels with the same layout); black elsewhere.
// Every frame carries the frame stamp (frame_stamp.h) in its top-left corner.
#pragma once

#include <opencv2/core.hpp>

#include "k40t_driver/sim/video/frame_stamp.h"
#include "k40t_driver/sim/video/thermal_renderer.h"
#include "k40t_driver/sim/video/video_snapshot.h"
#include "k40t_driver/sim/video/visible_renderer.h"

namespace k40t::sim::video {

// Size of the frames streamed in this snapshot's image mode and resolution.
cv::Size frame_size(const VideoSnapshot& snapshot);

class FrameRenderer {
 public:
  // A new BGR frame (the caller owns it) with `stamp` drawn in.
  cv::Mat render(const VideoSnapshot& snapshot, const FrameStamp& stamp);

 private:
  ThermalRenderer thermal_;
  VisibleRenderer visible_;
};

}  // namespace k40t::sim::video
