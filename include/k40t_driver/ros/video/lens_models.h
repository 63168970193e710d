// camera_info for whatever the stream shows: one camera_info_manager per lens (tele, wide,
// thermal; each with its own URL and set_camera_info service under ~tele, ~wide, ~thermal), or
// the lens's nominal optics as an ideal pinhole when it is not calibrated; resized to the frame
// and scaled by the zoom the pod reports:
//   tele     optical part: focal length reported (0x000005) / focal length at calibration;
//            digital part (above the optical range): zoom ratio / optical ratio
//   thermal  the thermal digital zoom (0x000105, read back through the driver's settings)
//   wide     the configured wide digital zoom (the pod reports none)
// Split screen: the image's camera_info is the tele's, placed where the left panel is in the frame;
// split_panels() describes both panels (the thermal one with the thermal lens and its zoom), each
// placed into the frame's pixel coordinates with the panel as roi, for locate_pixel.
// Distortion coefficients are those of the calibration, unchanged.
#pragma once

#include <array>
#include <memory>
#include <string>

#include <camera_info_manager/camera_info_manager.h>
#include <ros/node_handle.h>
#include <sensor_msgs/CameraInfo.h>

#include "k40t_driver/ros/video/video_config.h"
#include "k40t_driver/video/intrinsics.h"
#include "k40t_driver/video/lens_zoom.h"

namespace k40t::driver {

using video::TeleZoom;
using video::ZoomState;

class LensModels {
 public:
  LensModels(const ros::NodeHandle& private_nh, const VideoConfig& config);

  sensor_msgs::CameraInfo camera_info(const video::StreamView& view, cv::Size frame,
                                      const ZoomState& zoom) const;
  // Split screen: {visible panel, thermal panel}, K in the whole frame's pixel coordinates, roi
  // the panel's rectangle; frame ids are the caller's.
  std::array<sensor_msgs::CameraInfo, 2> split_panels(cv::Size frame, const ZoomState& zoom) const;

 private:
  bool calibrated(video::Lens lens) const;
  video::Intrinsics at_1x(video::Lens lens, cv::Size frame) const;
  // The lens's intrinsics for an `image`-sized picture at the zoom the pod reports.
  video::Intrinsics zoomed(video::Lens lens, cv::Size image, const ZoomState& zoom) const;
  sensor_msgs::CameraInfo to_message(video::Lens lens, const video::Intrinsics& in) const;

  const VideoConfig& config_;
  std::array<std::unique_ptr<camera_info_manager::CameraInfoManager>, 3> managers_;
  // Per lens: where camera_info_manager looks when no URL is set (empty: a URL is set).
  std::array<std::string, 3> default_files_;
};

}  // namespace k40t::driver
