#include "k40t_driver/sim/video/pinhole_view.h"

#include <algorithm>
#include <cmath>

namespace k40t::sim::video {

namespace {
constexpr double kDegToRad = 3.14159265358979323846 / 180.0;

cv::Vec3d to_vec(const WorldDirection& d) {
  return {d.north, d.east, d.up};
}
}  // namespace

LensOptics tele_optics() {
  return {4.7, 5.6, 11.0, 160.0};
}

LensOptics thermal_optics() {
  return {13.0, 640 * 0.012, 1.0, 8.0};
}

double focal_px(const LensOptics& optics, double zoom, int width_px) {
  const double z = std::clamp(zoom, 1.0, std::max(1.0, optics.max_zoom));
  return width_px * optics.focal_length_mm / optics.sensor_width_mm * z;
}

WorldDirection direction_of(double yaw_deg, double pitch_deg) {
  const double y = yaw_deg * kDegToRad;
  const double p = pitch_deg * kDegToRad;
  return {std::cos(p) * std::cos(y), std::cos(p) * std::sin(y), std::sin(p)};
}

PinholeView::PinholeView(double yaw_deg, double pitch_deg, double focal_px, cv::Size size)
    : pitch_rad_(pitch_deg * kDegToRad),
      focal_px_(focal_px),
      size_(size),
      centre_((size.width - 1) / 2.0, (size.height - 1) / 2.0) {
  const double y = yaw_deg * kDegToRad;
  const double p = pitch_rad_;
  forward_ = to_vec(direction_of(yaw_deg, pitch_deg));
  right_ = {-std::sin(y), std::cos(y), 0};
  up_ = {-std::sin(p) * std::cos(y), -std::sin(p) * std::sin(y), std::cos(p)};
}

WorldDirection PinholeView::ray(double u, double v) const {
  const double nx = (u - centre_.x) / focal_px_;
  const double ny = -(v - centre_.y) / focal_px_;
  const cv::Vec3d d = cv::normalize(forward_ + right_ * nx + up_ * ny);
  return {d[0], d[1], d[2]};
}

std::optional<cv::Point2d> PinholeView::project(const WorldDirection& direction) const {
  const cv::Vec3d d = to_vec(direction);
  const double depth = d.dot(forward_);
  if (depth <= 1e-9) return std::nullopt;
  return cv::Point2d(centre_.x + focal_px_ * d.dot(right_) / depth,
                     centre_.y - focal_px_ * d.dot(up_) / depth);
}

double PinholeView::horizon_row() const {
  return centre_.y + focal_px_ * std::tan(pitch_rad_);
}

}  // namespace k40t::sim::video
