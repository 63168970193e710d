#include "k40t_driver/sim/video/scene_canvas.h"

#include <algorithm>
#include <cmath>

#include <opencv2/imgproc.hpp>

#include "k40t_driver/sim/video/clip.h"

namespace k40t::sim::video {

namespace {
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;
constexpr double kHersheyHeightPx = 22;  // FONT_HERSHEY_SIMPLEX cap height at scale 1
constexpr int kDiscSegments = 180;

cv::Point to_pixel(const cv::Point2d& p) {
  return {static_cast<int>(std::lround(p.x)), static_cast<int>(std::lround(p.y))};
}

cv::Vec3d vec(const Vec3& d) {
  return {d.x, d.y, d.z};
}
}  // namespace

SceneCanvas::SceneCanvas(cv::Mat& image, const PinholeView& view)
    : image_(image), view_(view), bounds_(-2, -2, image.cols + 4, image.rows + 4) {}

void SceneCanvas::polyline(const std::vector<Vec3>& points, const cv::Scalar& colour,
                           int thickness_px) {
  std::optional<cv::Point2d> previous;
  for (const Vec3& d : points) {
    const std::optional<cv::Point2d> p = view_.project(d);
    if (p && previous) {
      if (auto piece = clip_segment(*previous, *p, bounds_)) {
        cv::line(image_, to_pixel(piece->first), to_pixel(piece->second), colour, thickness_px,
                 cv::LINE_AA);
      }
    }
    previous = p;
  }
}

void SceneCanvas::fill(const std::vector<Vec3>& corners, const cv::Scalar& colour) {
  std::vector<cv::Point2d> projected;
  for (const Vec3& d : corners) {
    const std::optional<cv::Point2d> p = view_.project(d);
    if (!p) return;
    projected.push_back(*p);
  }
  const std::vector<cv::Point2d> clipped = clip_polygon(projected, bounds_);
  if (clipped.size() < 3) return;
  std::vector<cv::Point> pixels;
  for (const cv::Point2d& p : clipped) pixels.push_back(to_pixel(p));
  cv::fillPoly(image_, std::vector<std::vector<cv::Point>>{pixels}, colour, cv::LINE_AA);
}

void SceneCanvas::disc(const Vec3& centre, double radius_deg, const cv::Scalar& colour) {
  const cv::Vec3d c = vec(centre);
  // Two unit vectors perpendicular to the centre direction span the disc's rim.
  const cv::Vec3d helper = std::abs(c[2]) < 0.9 ? cv::Vec3d(0, 0, 1) : cv::Vec3d(1, 0, 0);
  const cv::Vec3d e1 = cv::normalize(c.cross(helper));
  const cv::Vec3d e2 = c.cross(e1);
  const double r = radius_deg * kDegToRad;
  std::vector<Vec3> rim;
  for (int i = 0; i < kDiscSegments; ++i) {
    const double t = 2 * 3.14159265358979323846 * i / kDiscSegments;
    const cv::Vec3d p = c * std::cos(r) + (e1 * std::cos(t) + e2 * std::sin(t)) * std::sin(r);
    rim.push_back(Vec3{p[0], p[1], p[2]});
  }
  fill(rim, colour);
}

void SceneCanvas::label(const Vec3& anchor, const std::string& text, double height_deg,
                        const cv::Scalar& colour) {
  const std::optional<cv::Point2d> p = view_.project(anchor);
  if (!p) return;
  const double height_px = view_.focal_px() * std::tan(height_deg * kDegToRad);
  if (height_px < 6 || height_px > image_.rows) return;
  const double scale = height_px / kHersheyHeightPx;
  const int thickness = std::max(1, static_cast<int>(scale * 2));
  const cv::Size extent =
      cv::getTextSize(text, cv::FONT_HERSHEY_SIMPLEX, scale, thickness, nullptr);
  if (!cv::Rect2d(-extent.width, 0, image_.cols + extent.width, image_.rows + extent.height)
           .contains(*p)) {
    return;
  }
  cv::putText(image_, text, to_pixel(*p), cv::FONT_HERSHEY_SIMPLEX, scale, colour, thickness,
              cv::LINE_AA);
}

}  // namespace k40t::sim::video
