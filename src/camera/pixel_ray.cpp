#include "k40t_driver/camera/pixel_ray.h"

#include <algorithm>
#include <cmath>

#include "k40t_driver/camera/opencv_lens.h"

namespace k40t::camera {

namespace {

// OpenCV's pinhole model takes 4, 5, 8, 12 or 14 coefficients (k1 k2 p1 p2 [k3 [k4 k5 k6 [s1..s4
// [tx ty]]]]): plumb_bob is the first five, rational_polynomial the first eight.
bool opencv_pinhole_count(size_t n) {
  return n == 4 || n == 5 || n == 8 || n == 12 || n == 14;
}

Result<LensModel> model_of(const CameraModel& camera) {
  if (!has_distortion(camera)) return LensModel::kNone;
  const std::string& name = camera.distortion_model;
  if ((name == "plumb_bob" || name == "rational_polynomial") &&
      opencv_pinhole_count(camera.D.size()))
    return LensModel::kPinholeFamily;
  if (name == "equidistant" && camera.D.size() == 4) return LensModel::kFisheye;
  return Result<LensModel>::fail("camera_info distortion model '" + name + "' with " +
                                 std::to_string(camera.D.size()) +
                                 " coefficients is not supported (plumb_bob: 5, "
                                 "rational_polynomial: 8, equidistant: 4)");
}

Status check_focal(const CameraModel& camera) {
  if (!(camera.K[0] > 0 && camera.K[4] > 0) || !std::isfinite(camera.K[0]) ||
      !std::isfinite(camera.K[4]))
    return Status::fail("camera_info has no intrinsics (K)");
  return Status::ok();
}

}  // namespace

bool has_distortion(const CameraModel& camera) {
  return std::any_of(camera.D.begin(), camera.D.end(), [](double d) { return d != 0.0; });
}

Result<std::array<double, 2>> pixel_to_normalised(const CameraModel& camera, double u, double v) {
  if (Status s = check_focal(camera); !s.is_ok()) return s;
  const Result<LensModel> model = model_of(camera);
  if (!model) return model.status();
  const Result<const OpenCvLens*> lens = opencv_lens();
  if (!lens) return lens.status();
  return lens.value()->undistort(camera, model.value(), u, v);
}

Result<std::array<double, 2>> project_ray(const CameraModel& camera,
                                          const std::array<double, 3>& ray) {
  if (Status s = check_focal(camera); !s.is_ok()) return s;
  if (!(ray[2] > 0)) return Result<std::array<double, 2>>::fail("the ray points behind the camera");
  const Result<LensModel> model = model_of(camera);
  if (!model) return model.status();
  const Result<const OpenCvLens*> lens = opencv_lens();
  if (!lens) return lens.status();
  return lens.value()->project(camera, model.value(), ray);
}

}  // namespace k40t::camera
