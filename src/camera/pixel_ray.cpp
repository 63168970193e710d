#include "k40t_driver/camera/pixel_ray.h"

#include <algorithm>
#include <cmath>

#include <opencv2/calib3d.hpp>

namespace k40t::camera {

namespace {

enum class Model { kNone, kPinholeFamily, kFisheye };

// OpenCV's pinhole model takes 4, 5, 8, 12 or 14 coefficients (k1 k2 p1 p2 [k3 [k4 k5 k6 [s1..s4
// [tx ty]]]]): plumb_bob is the first five, rational_polynomial the first eight.
bool opencv_pinhole_count(size_t n) {
  return n == 4 || n == 5 || n == 8 || n == 12 || n == 14;
}

Result<Model> model_of(const CameraModel& camera) {
  if (!has_distortion(camera)) return Model::kNone;
  const std::string& name = camera.distortion_model;
  if ((name == "plumb_bob" || name == "rational_polynomial") &&
      opencv_pinhole_count(camera.D.size()))
    return Model::kPinholeFamily;
  if (name == "equidistant" && camera.D.size() == 4) return Model::kFisheye;
  return Result<Model>::fail("camera_info distortion model '" + name + "' with " +
                             std::to_string(camera.D.size()) +
                             " coefficients is not supported (plumb_bob: 5, "
                             "rational_polynomial: 8, equidistant: 4)");
}

cv::Matx33d camera_matrix(const CameraModel& camera) {
  return cv::Matx33d(camera.K.data());
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
  const Result<Model> model = model_of(camera);
  if (!model) return model.status();
  const std::vector<cv::Point2d> in{{u, v}};
  std::vector<cv::Point2d> out;
  switch (model.value()) {
    case Model::kNone:
      cv::undistortPoints(in, out, camera_matrix(camera), cv::noArray());
      break;
    case Model::kPinholeFamily:
      // More iterations than the default 5: strong barrel distortion at the image corners
      // converges slowly, and the ray should not carry the solver's residual.
      cv::undistortPoints(
          in, out, camera_matrix(camera), camera.D, cv::noArray(), cv::noArray(),
          cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-12));
      break;
    case Model::kFisheye:
      cv::fisheye::undistortPoints(in, out, camera_matrix(camera), camera.D);
      break;
  }
  return std::array<double, 2>{out[0].x, out[0].y};
}

Result<std::array<double, 2>> project_ray(const CameraModel& camera,
                                          const std::array<double, 3>& ray) {
  if (Status s = check_focal(camera); !s.is_ok()) return s;
  if (!(ray[2] > 0)) return Result<std::array<double, 2>>::fail("the ray points behind the camera");
  const Result<Model> model = model_of(camera);
  if (!model) return model.status();
  const std::vector<cv::Point3d> in{{ray[0], ray[1], ray[2]}};
  std::vector<cv::Point2d> out;
  const cv::Vec3d no_rotation(0, 0, 0), no_translation(0, 0, 0);
  if (model.value() == Model::kFisheye) {
    cv::fisheye::projectPoints(in, out, no_rotation, no_translation, camera_matrix(camera),
                               camera.D);
  } else if (model.value() == Model::kPinholeFamily) {
    cv::projectPoints(in, no_rotation, no_translation, camera_matrix(camera), camera.D, out);
  } else {
    cv::projectPoints(in, no_rotation, no_translation, camera_matrix(camera), cv::noArray(), out);
  }
  return std::array<double, 2>{out[0].x, out[0].y};
}

}  // namespace k40t::camera
