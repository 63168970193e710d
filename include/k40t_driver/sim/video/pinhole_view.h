// An ideal pinhole camera on the gimbal (no roll, no distortion, square pixels, principal point
// at the image centre), looking along sim/geometry.h's camera_basis(): the model the simulated
// frames are rendered with, and therefore the intrinsics the video nodelet's default camera_info
// describes (fx = fy = focal_px, cx = (width - 1) / 2, cy = (height - 1) / 2).
#pragma once

#include <optional>

#include <opencv2/core.hpp>

#include "k40t_driver/sim/geometry.h"
#include "k40t_driver/sim/lens.h"

namespace k40t::sim::video {

// Focal length in pixels of `lens` (sim/lens.h) at hybrid `zoom` (clamped to the lens's range) in
// an image `width_px` wide: width * focal length * zoom / sensor width. Optical and digital zoom
// scale it the same way.
double focal_px(Lens lens, double zoom, int width_px);

class PinholeView {
 public:
  PinholeView(double yaw_deg, double pitch_deg, double focal_px, cv::Size size);

  // The unit ray through the centre of pixel (u, v); fractional coordinates are allowed.
  Vec3 ray(double u, double v) const;
  // Where a direction lands in the image (may be outside it); nothing when behind the camera.
  std::optional<cv::Point2d> project(const Vec3& direction) const;

  double focal_px() const { return focal_px_; }
  cv::Size size() const { return size_; }
  // Image row of the horizon (elevation 0); rows below it look at the ground.
  double horizon_row() const;

 private:
  CameraBasis basis_;
  double pitch_deg_;
  double focal_px_;
  cv::Size size_;
  cv::Point2d centre_;
};

}  // namespace k40t::sim::video
