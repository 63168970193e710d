// Thermal frames of the simulated pod: the temperature scene seen through the thermal lens at
// its digital zoom, normalised over the image (automatic gain, as the camera's own AGC does:
// coldest in view -> table entry 0, hottest -> 255) and coloured with the selected palette.
#pragma once

#include <tuple>

#include <opencv2/core.hpp>

#include "k40t_driver/sim/video/video_snapshot.h"
#include "k40t_driver/video/stream_view.h"

namespace k40t::sim::video {

using k40t::video::kThermalHeight;
using k40t::video::kThermalWidth;

class ThermalRenderer {
 public:
  // A 640 x 512 BGR image. The temperature field is sampled every `kSampleStepPx` pixels and
  // interpolated in between, and kept until the view or the scene changes, so a still gimbal
  // costs only the palette lookup. Palette codes outside 1..20 draw white hot.
  const cv::Mat& render(const VideoSnapshot& snapshot);

  // The field behind the last image, degC per pixel (CV_32F), for tests.
  const cv::Mat& temperatures() const { return temperatures_; }

  static constexpr int kSampleStepPx = 4;

 private:
  using ViewKey = std::tuple<double, double, int, uint64_t, bool>;
  void sample(const VideoSnapshot& snapshot);

  ViewKey view_;
  int palette_ = 0;
  bool valid_ = false;
  cv::Mat temperatures_;
  cv::Mat normalised_;
  cv::Mat image_;
};

}  // namespace k40t::sim::video
