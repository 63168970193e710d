// An ideal pinhole camera on the gimbal (no roll, no distortion, square pixels, principal point
// at the image centre): the model the simulated frames are rendered with, and therefore the
// intrinsics the video nodelet's default camera_info describes (fx = fy = focal_px,
// cx = (width - 1) / 2, cy = (height - 1) / 2).
#pragma once

#include <optional>

#include <opencv2/core.hpp>

#include "k40t_driver/sim/video/video_snapshot.h"

namespace k40t::sim::video {

// A lens at 1x: focal length and the width of the sensor area the stream shows. The focal
// length in pixels is width_px * focal_mm / sensor_width_mm, times the zoom.
struct LensOptics {
  double focal_length_mm = 0;
  double sensor_width_mm = 0;
  double max_optical_zoom = 1;  // above it the zoom is a digital crop
  double max_zoom = 1;
};

// The simulator's lenses (the same optics as sim/lens.h): telephoto 4.7 mm on 5.6 mm, 11x optical
// and 160x hybrid; thermal 13 mm on 640 x 12 um, 8x digital.
LensOptics tele_optics();
LensOptics thermal_optics();

// Focal length in pixels of `optics` at `zoom` (clamped to 1..max_zoom) in an image `width_px`
// wide. Optical and digital zoom scale it the same way.
double focal_px(const LensOptics& optics, double zoom, int width_px);

class PinholeView {
 public:
  PinholeView(double yaw_deg, double pitch_deg, double focal_px, cv::Size size);

  // The unit ray through the centre of pixel (u, v); fractional coordinates are allowed.
  WorldDirection ray(double u, double v) const;
  // Where a direction lands in the image (may be outside it); nothing when behind the camera.
  std::optional<cv::Point2d> project(const WorldDirection& direction) const;

  double focal_px() const { return focal_px_; }
  cv::Size size() const { return size_; }
  // Image row of the horizon (elevation 0); rows below it look at the ground.
  double horizon_row() const;

 private:
  cv::Vec3d forward_;
  cv::Vec3d right_;
  cv::Vec3d up_;
  double pitch_rad_;
  double focal_px_;
  cv::Size size_;
  cv::Point2d centre_;
};

// Direction of a heading and elevation in degrees (yaw positive to the right, pitch up).
WorldDirection direction_of(double yaw_deg, double pitch_deg);

}  // namespace k40t::sim::video
