// The camera_info that describes a pixel of the current image, for locate_pixel: the image's own
// (`camera_info`) or, in split screen, that of the panel holding the pixel
// (`split/visible/camera_info`, `split/thermal/camera_info`, published by the video node with the
// image's stamp; camera/view_select.h picks), and the lens model of pixel_ray.h it gives.
#pragma once

#include <array>
#include <mutex>
#include <optional>

#include <ros/node_handle.h>
#include <ros/subscriber.h>
#include <sensor_msgs/CameraInfo.h>

#include "k40t_driver/camera/pixel_ray.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::driver {

class CameraViews {
 public:
  explicit CameraViews(ros::NodeHandle nh);

  // The camera_info for pixel (u, v), or why there is none (no camera_info yet, or a split-screen
  // pixel in neither panel).
  Result<sensor_msgs::CameraInfo> for_pixel(double u, double v) const;

 private:
  std::array<ros::Subscriber, 3> subscribers_;  // the image's, visible panel, thermal panel
  mutable std::mutex mutex_;
  std::optional<sensor_msgs::CameraInfo> image_;
  std::array<std::optional<sensor_msgs::CameraInfo>, 2> panels_;
};

// pixel_ray.h's model of a camera_info: K, distortion model and D.
camera::CameraModel camera_model(const sensor_msgs::CameraInfo& info);

}  // namespace k40t::driver
