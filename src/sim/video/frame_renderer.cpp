#include "k40t_driver/sim/video/frame_renderer.h"

#include <opencv2/imgproc.hpp>

#include "k40t_driver/video/stream_view.h"

namespace k40t::sim::video {

cv::Size frame_size(const VideoSnapshot& snapshot) {
  if (snapshot.image_mode == ImageMode::kThermal) return {kThermalWidth, kThermalHeight};
  return snapshot.resolution == StreamResolution::k720p ? cv::Size(1280, 720)
                                                        : cv::Size(1920, 1080);
}

cv::Mat FrameRenderer::render(const VideoSnapshot& snapshot, const FrameStamp& stamp) {
  const cv::Size size = frame_size(snapshot);
  cv::Mat frame;
  switch (snapshot.image_mode) {
    case ImageMode::kThermal:
      frame = thermal_.render(snapshot).clone();
      break;
    case ImageMode::kSplit: {
      frame = cv::Mat::zeros(size, CV_8UC3);
      const k40t::video::SplitLayout layout = k40t::video::split_layout(size);
      cv::resize(visible_.render(snapshot, size), frame(layout.visible), layout.visible.size(), 0,
                 0, cv::INTER_AREA);
      cv::resize(thermal_.render(snapshot), frame(layout.thermal), layout.thermal.size(), 0, 0,
                 cv::INTER_LINEAR);
      break;
    }
    case ImageMode::kVisible:
    case ImageMode::kVisibleAlt:
    default:
      frame = visible_.render(snapshot, size).clone();
      break;
  }
  draw_frame_stamp(frame, stamp);
  return frame;
}

}  // namespace k40t::sim::video
