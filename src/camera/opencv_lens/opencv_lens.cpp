// libk40t_opencv_lens.so: the only code that calls OpenCV's calib3d (camera/opencv_lens.h says
// why it is a library of its own). Lens distortion is OpenCV's own (cv::undistortPoints /
// cv::projectPoints, and cv::fisheye for "equidistant"), never a model written here.
#include <opencv2/calib3d.hpp>

#include "k40t_driver/camera/opencv_lens.h"

namespace k40t::camera {

namespace {

cv::Matx33d camera_matrix(const CameraModel& camera) {
  return cv::Matx33d(camera.K.data());
}

std::array<double, 2> undistort(const CameraModel& camera, LensModel model, double u, double v) {
  const std::vector<cv::Point2d> in{{u, v}};
  std::vector<cv::Point2d> out;
  switch (model) {
    case LensModel::kNone:
      cv::undistortPoints(in, out, camera_matrix(camera), cv::noArray());
      break;
    case LensModel::kPinholeFamily:
      // More iterations than the default 5: strong barrel distortion at the image corners
      // converges slowly, and the ray should not carry the solver's residual.
      cv::undistortPoints(
          in, out, camera_matrix(camera), camera.D, cv::noArray(), cv::noArray(),
          cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 100, 1e-12));
      break;
    case LensModel::kFisheye:
      cv::fisheye::undistortPoints(in, out, camera_matrix(camera), camera.D);
      break;
  }
  return {out[0].x, out[0].y};
}

std::array<double, 2> project(const CameraModel& camera, LensModel model,
                              const std::array<double, 3>& ray) {
  const std::vector<cv::Point3d> in{{ray[0], ray[1], ray[2]}};
  std::vector<cv::Point2d> out;
  const cv::Vec3d no_rotation(0, 0, 0), no_translation(0, 0, 0);
  if (model == LensModel::kFisheye) {
    cv::fisheye::projectPoints(in, out, no_rotation, no_translation, camera_matrix(camera),
                               camera.D);
  } else if (model == LensModel::kPinholeFamily) {
    cv::projectPoints(in, no_rotation, no_translation, camera_matrix(camera), camera.D, out);
  } else {
    cv::projectPoints(in, no_rotation, no_translation, camera_matrix(camera), cv::noArray(), out);
  }
  return {out[0].x, out[0].y};
}

constexpr OpenCvLens kFunctions{undistort, project};

}  // namespace

}  // namespace k40t::camera

// The symbol camera::opencv_lens() looks up (kOpenCvLensSymbol).
extern "C" __attribute__((visibility("default"))) const k40t::camera::OpenCvLens*
k40t_opencv_lens() {
  return &k40t::camera::kFunctions;
}
