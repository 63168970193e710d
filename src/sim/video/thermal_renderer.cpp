#include "k40t_driver/sim/video/thermal_renderer.h"

#include <algorithm>

#include <opencv2/imgproc.hpp>

#include "k40t_driver/sim/video/palette.h"
#include "k40t_driver/sim/video/pinhole_view.h"

namespace k40t::sim::video {

namespace {
constexpr double kUniformSceneDegC = 20;
constexpr double kMinimumSpanDegC = 2;  // a uniform scene stays mid-table, not noise-stretched
}  // namespace

void ThermalRenderer::sample(const VideoSnapshot& snapshot) {
  const cv::Size size(kThermalWidth, kThermalHeight);
  const int zoom = std::clamp(snapshot.thermal_zoom, 1, 8);
  const PinholeView view(snapshot.yaw_deg, snapshot.pitch_deg,
                         focal_px(Lens::kThermal, zoom, size.width), size);
  const int step = kSampleStepPx;
  cv::Mat coarse(size.height / step, size.width / step, CV_32F);
  for (int row = 0; row < coarse.rows; ++row) {
    float* out = coarse.ptr<float>(row);
    for (int col = 0; col < coarse.cols; ++col) {
      // The centre of the step x step block this sample stands for.
      const double u = col * step + (step - 1) / 2.0;
      const double v = row * step + (step - 1) / 2.0;
      out[col] = static_cast<float>(snapshot.temperature ? snapshot.temperature(view.ray(u, v))
                                                         : kUniformSceneDegC);
    }
  }
  cv::resize(coarse, temperatures_, size, 0, 0, cv::INTER_LINEAR);

  double lo = 0;
  double hi = 0;
  cv::minMaxLoc(temperatures_, &lo, &hi);
  if (hi - lo < kMinimumSpanDegC) {
    const double mid = (hi + lo) / 2;
    lo = mid - kMinimumSpanDegC / 2;
    hi = mid + kMinimumSpanDegC / 2;
  }
  temperatures_.convertTo(normalised_, CV_8U, 255.0 / (hi - lo), -lo * 255.0 / (hi - lo));
  cv::cvtColor(normalised_, normalised_, cv::COLOR_GRAY2BGR);  // cv::LUT wants matching channels
}

const cv::Mat& ThermalRenderer::render(const VideoSnapshot& snapshot) {
  const ViewKey view{snapshot.yaw_deg, snapshot.pitch_deg, snapshot.thermal_zoom,
                     snapshot.scene_version, static_cast<bool>(snapshot.temperature)};
  const bool resample = !valid_ || view != view_;
  if (resample) sample(snapshot);
  if (resample || snapshot.palette != palette_) {
    Result<cv::Mat> table = palette_table(snapshot.palette);
    cv::LUT(normalised_, table ? table.value() : palette_table(kFirstPalette).value(), image_);
    palette_ = snapshot.palette;
  }
  view_ = view;
  valid_ = true;
  return image_;
}

}  // namespace k40t::sim::video
