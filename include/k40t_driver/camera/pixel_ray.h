// A pixel of an image described by a ROS camera_info (K, distortion model and D) to the direction
// of its ray in the camera's optical frame (z forward, x right, y down), and back. Lens
// distortion is OpenCV's own (cv::undistortPoints / cv::projectPoints, and cv::fisheye for
// "equidistant"), never a model written here, in a library opened on the first call
// (opencv_lens.h). ROS-free: the caller copies the message's fields.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "k40t_driver/protocol/result.h"

namespace k40t::camera {

struct CameraModel {
  std::array<double, 9> K{};     // row-major: fx 0 cx / 0 fy cy / 0 0 1 (skew allowed)
  std::string distortion_model;  // "plumb_bob", "rational_polynomial", "equidistant" or empty
  std::vector<double> D;         // empty or all zero: no distortion
};

// The undistorted normalised image point (x, y) of pixel (u, v): the ray is (x, y, 1). Fails on
// a K without focal lengths, a non-zero D of a model OpenCV does not know, or when the lens
// library cannot be opened.
Result<std::array<double, 2>> pixel_to_normalised(const CameraModel& camera, double u, double v);

// Where the ray (x, y, z) of the optical frame appears in the (distorted) image; fails when the
// ray does not point ahead of the camera (z <= 0) or the model is not known.
Result<std::array<double, 2>> project_ray(const CameraModel& camera,
                                          const std::array<double, 3>& ray);

// Whether D has any non-zero coefficient.
bool has_distortion(const CameraModel& camera);

}  // namespace k40t::camera
