// Visible (telephoto) frames of the simulated pod: a synthetic landscape fixed in the world —
// sky and ground split at the horizon, a heading grid on the ground with labels every 10 deg,
// coloured towers on the horizon, and ring targets whose rings halve in size down to what only
// the longest zoom resolves — seen through the telephoto lens at the hybrid zoom. Turning the
// gimbal moves the scene across the image; zooming magnifies it. Everything is drawn at the
// output resolution, so detail stays sharp at 160x.
#pragma once

#include <tuple>

#include <opencv2/core.hpp>

#include "k40t_driver/sim/video/video_snapshot.h"

namespace k40t::sim::video {

class VisibleRenderer {
 public:
  // A BGR image of `size`; kept until the view changes, so a still gimbal costs nothing.
  const cv::Mat& render(const VideoSnapshot& snapshot, cv::Size size);

 private:
  using ViewKey = std::tuple<double, double, double, int, int>;
  ViewKey view_;
  bool valid_ = false;
  cv::Mat image_;
};

}  // namespace k40t::sim::video
