#include "k40t_driver/ros/camera_views.h"

#include <algorithm>

#include "k40t_driver/camera/view_select.h"

namespace k40t::driver {

namespace {
// Panels are published with every split-screen frame (30 Hz) and the image's stamp: a panel
// half a second older than the image is from a split screen that has ended.
constexpr int64_t kPanelMaxSkewNs = 500000000;
const std::array<const char*, 2> kPanelNames{"visible panel", "thermal panel"};
}  // namespace

CameraViews::CameraViews(ros::NodeHandle nh) {
  subscribers_[0] = nh.subscribe<sensor_msgs::CameraInfo>(
      "camera_info", 1, [this](const sensor_msgs::CameraInfo::ConstPtr& msg) {
        std::lock_guard<std::mutex> lock(mutex_);
        image_ = *msg;
      });
  const std::array<const char*, 2> topics{"split/visible/camera_info", "split/thermal/camera_info"};
  for (size_t i = 0; i < topics.size(); ++i) {
    subscribers_[i + 1] = nh.subscribe<sensor_msgs::CameraInfo>(
        topics[i], 1, [this, i](const sensor_msgs::CameraInfo::ConstPtr& msg) {
          std::lock_guard<std::mutex> lock(mutex_);
          panels_[i] = *msg;
        });
  }
}

Result<sensor_msgs::CameraInfo> CameraViews::for_pixel(double u, double v) const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!image_) {
    return Result<sensor_msgs::CameraInfo>::fail(
        "no camera_info received (start the video: video:=true)");
  }
  std::vector<camera::ViewCandidate> candidates;
  std::vector<const sensor_msgs::CameraInfo*> infos;
  for (size_t i = 0; i < panels_.size(); ++i) {
    if (!panels_[i]) continue;
    const sensor_msgs::RegionOfInterest& roi = panels_[i]->roi;
    candidates.push_back({static_cast<int64_t>(panels_[i]->header.stamp.toNSec()),
                          {roi.x_offset, roi.y_offset, roi.width, roi.height},
                          kPanelNames[i]});
    infos.push_back(&*panels_[i]);
  }
  const Result<std::optional<size_t>> chosen = camera::select_view(
      static_cast<int64_t>(image_->header.stamp.toNSec()), candidates, u, v, kPanelMaxSkewNs);
  if (!chosen) return chosen.status();
  return chosen.value() ? *infos[*chosen.value()] : *image_;
}

camera::CameraModel camera_model(const sensor_msgs::CameraInfo& info) {
  camera::CameraModel model;
  std::copy(info.K.begin(), info.K.end(), model.K.begin());
  model.distortion_model = info.distortion_model;
  model.D = info.D;
  return model;
}

}  // namespace k40t::driver
