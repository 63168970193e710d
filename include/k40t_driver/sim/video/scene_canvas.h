// Drawing in world directions onto the image of a PinholeView: lines, filled shapes and labels are
// given as directions (or headings/elevations) and land where the camera sees them, at any zoom.
#pragma once

#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "k40t_driver/sim/video/pinhole_view.h"

namespace k40t::sim::video {

class SceneCanvas {
 public:
  SceneCanvas(cv::Mat& image, const PinholeView& view);

  // A line through `points` (pieces behind the camera are left out).
  void polyline(const std::vector<Vec3>& points, const cv::Scalar& colour, int thickness_px);
  // A filled shape; drawn only when every corner is in front of the camera.
  void fill(const std::vector<Vec3>& corners, const cv::Scalar& colour);
  // A disc of angular radius `radius_deg` around `centre`.
  void disc(const Vec3& centre, double radius_deg, const cv::Scalar& colour);
  // Text whose lower-left corner is at `anchor`, `height_deg` tall; skipped when too small to
  // read or larger than the image.
  void label(const Vec3& anchor, const std::string& text, double height_deg,
             const cv::Scalar& colour);

  const PinholeView& view() const { return view_; }

 private:
  cv::Mat& image_;
  const PinholeView& view_;
  cv::Rect2d bounds_;
};

}  // namespace k40t::sim::video
