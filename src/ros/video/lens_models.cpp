#include "k40t_driver/ros/video/lens_models.h"

#include <sys/stat.h>
#include <algorithm>
#include <cstdlib>
#include <string>

namespace k40t::driver {

namespace {

constexpr std::array<video::Lens, 3> kLenses{video::Lens::kTele, video::Lens::kWide,
                                             video::Lens::kThermal};

const NominalOptics& nominal(const VideoConfig& config, video::Lens lens) {
  switch (lens) {
    case video::Lens::kWide:
      return config.wide;
    case video::Lens::kThermal:
      return config.thermal;
    case video::Lens::kTele:
      break;
  }
  return config.tele;
}

video::Intrinsics from_message(const sensor_msgs::CameraInfo& info) {
  video::Intrinsics in;
  std::copy(info.K.begin(), info.K.end(), in.K.begin());
  std::copy(info.P.begin(), info.P.end(), in.P.begin());
  in.width = static_cast<int>(info.width);
  in.height = static_cast<int>(info.height);
  return in;
}

// camera_info_manager's file for an empty URL: ${ROS_HOME}/camera_info/<camera name>.yaml.
std::string default_calibration_file(const std::string& camera_name) {
  const char* ros_home = std::getenv("ROS_HOME");
  const char* home = std::getenv("HOME");
  const std::string dir = ros_home ? ros_home : std::string(home ? home : "") + "/.ros";
  return dir + "/camera_info/" + camera_name + ".yaml";
}

bool file_exists(const std::string& path) {
  struct stat info {};
  return ::stat(path.c_str(), &info) == 0;
}

}  // namespace

LensModels::LensModels(const ros::NodeHandle& private_nh, const VideoConfig& config)
    : config_(config) {
  for (video::Lens lens : kLenses) {
    const std::string name = video::to_string(lens);
    ros::NodeHandle lens_nh(private_nh, name);
    const std::string& url = config.calibration_urls[static_cast<size_t>(lens)];
    if (url.empty())
      default_files_[static_cast<size_t>(lens)] =
          default_calibration_file(config.frame_prefix + name);
    managers_[static_cast<size_t>(lens)] = std::make_unique<camera_info_manager::CameraInfoManager>(
        lens_nh, config.frame_prefix + name, url);
  }
}

bool LensModels::calibrated(video::Lens lens) const {
  // camera_info_manager loads on the first isCalibrated() and warns "Camera calibration file ...
  // not found" when no URL is set and no calibration was ever saved: the documented
  // nominal-pinhole case (docs/video.md), not a warning. So it is asked only once a file is there
  // (set_camera_info, i.e. camera_calibration, saves it there) or when the user set a URL.
  const std::string& default_file = default_files_[static_cast<size_t>(lens)];
  if (!default_file.empty() && !file_exists(default_file)) return false;
  return managers_[static_cast<size_t>(lens)]->isCalibrated();
}

video::Intrinsics LensModels::at_1x(video::Lens lens, cv::Size frame) const {
  auto& manager = *managers_[static_cast<size_t>(lens)];
  if (calibrated(lens)) {
    const sensor_msgs::CameraInfo info = manager.getCameraInfo();
    const video::Intrinsics saved = from_message(info);
    if (saved.width > 0 && saved.height > 0 &&
        (saved.width != frame.width || saved.height != frame.height)) {
      return video::resized(saved, frame.width, frame.height);
    }
    return saved;
  }
  const NominalOptics& optics = nominal(config_, lens);
  return video::ideal_pinhole(frame.width * optics.focal_length_mm / optics.sensor_width_mm,
                              frame.width, frame.height);
}

video::Intrinsics LensModels::zoomed(video::Lens lens, cv::Size image,
                                     const ZoomState& zoom) const {
  video::Intrinsics in = at_1x(lens, image);
  switch (lens) {
    case video::Lens::kTele: {
      const TeleZoom z =
          video::tele_zoom(config_.tele.focal_length_mm, config_.tele_max_optical_zoom, zoom,
                           calibrated(lens) ? config_.tele_calibration_focal_length_mm
                                            : config_.tele.focal_length_mm);
      return video::zoom_digital(video::zoom_optical(in, z.optical), z.digital);
    }
    case video::Lens::kThermal:
      return video::zoom_digital(in, std::clamp(zoom.thermal_zoom, 1, 8));
    case video::Lens::kWide:
      break;
  }
  return video::zoom_digital(in, config_.wide_digital_zoom);
}

sensor_msgs::CameraInfo LensModels::to_message(video::Lens lens,
                                               const video::Intrinsics& in) const {
  auto& manager = *managers_[static_cast<size_t>(lens)];
  sensor_msgs::CameraInfo info;
  if (calibrated(lens)) {
    const sensor_msgs::CameraInfo saved = manager.getCameraInfo();
    info.distortion_model = saved.distortion_model;
    info.D = saved.D;
    info.R = saved.R;
  } else {
    info.distortion_model = "plumb_bob";
    info.D.assign(5, 0.0);
    info.R = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  }
  std::copy(in.K.begin(), in.K.end(), info.K.begin());
  std::copy(in.P.begin(), in.P.end(), info.P.begin());
  info.width = static_cast<uint32_t>(in.width);
  info.height = static_cast<uint32_t>(in.height);
  return info;
}

sensor_msgs::CameraInfo LensModels::camera_info(const video::StreamView& view, cv::Size frame,
                                                const ZoomState& zoom) const {
  video::Intrinsics in = zoomed(view.lens, frame, zoom);
  if (view.split) {
    const video::SplitLayout layout = video::split_layout(frame);
    in = video::in_panel(in, layout.visible, frame);
  }
  return to_message(view.lens, in);
}

std::array<sensor_msgs::CameraInfo, 2> LensModels::split_panels(cv::Size frame,
                                                                const ZoomState& zoom) const {
  const video::SplitLayout layout = video::split_layout(frame);
  const cv::Size thermal(video::kThermalWidth, video::kThermalHeight);
  std::array<sensor_msgs::CameraInfo, 2> out{
      to_message(video::Lens::kTele,
                 video::in_panel(zoomed(video::Lens::kTele, frame, zoom), layout.visible, frame)),
      to_message(
          video::Lens::kThermal,
          video::in_panel(zoomed(video::Lens::kThermal, thermal, zoom), layout.thermal, frame))};
  const std::array<cv::Rect, 2> panels{layout.visible, layout.thermal};
  for (size_t i = 0; i < out.size(); ++i) {
    out[i].roi.x_offset = static_cast<uint32_t>(panels[i].x);
    out[i].roi.y_offset = static_cast<uint32_t>(panels[i].y);
    out[i].roi.width = static_cast<uint32_t>(panels[i].width);
    out[i].roi.height = static_cast<uint32_t>(panels[i].height);
  }
  return out;
}

}  // namespace k40t::driver
