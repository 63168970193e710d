// The video nodelet's parameters (config/video.yaml documents each, docs/video.md explains them).
#pragma once

#include <array>
#include <string>

#include <ros/node_handle.h>

#include "k40t_driver/protocol/result.h"
#include "k40t_driver/video/capture_options.h"
#include "k40t_driver/video/stamp_estimator.h"
#include "k40t_driver/video/stream_view.h"

namespace k40t::driver {

// A lens's nominal optics, for the default camera_info when no calibration is given: the focal
// length in pixels is image width * focal_length / sensor_width.
struct NominalOptics {
  double focal_length_mm = 0;
  double sensor_width_mm = 0;
};

struct VideoConfig {
  video::CaptureOptions capture;
  video::StampOptions stamps;
  std::string frame_prefix = "k40t_";
  video::Lens mode6_lens = video::Lens::kTele;
  // camera_info_manager URLs, indexed by video::Lens (tele, wide, thermal); empty = nominal.
  std::array<std::string, 3> calibration_urls;
  NominalOptics tele{4.7, 5.6};
  NominalOptics wide{4.0, 6.17};
  NominalOptics thermal{13.0, 7.68};
  double tele_max_optical_zoom = 11;
  // Focal length (mm) the tele calibration was taken at; intrinsics scale from there.
  double tele_calibration_focal_length_mm = 4.7;
  double wide_digital_zoom = 1;  // the pod reports none: set it with the zoom sent to the wide lens
  std::string settings_topic = "driver/parameter_updates";
  double expected_fps = 30;
  double stale_after_s = 0.5;  // diagnostics ERROR when the newest frame is older
  double diagnostic_period_s = 0.25;
};

Result<VideoConfig> read_video_config(const ros::NodeHandle& private_nh);

// The optical frame of a lens: frame_prefix + "tele_optical_frame" etc.
std::string optical_frame(const VideoConfig& config, video::Lens lens);

}  // namespace k40t::driver
