#include "k40t_driver/sim/video/pinhole_view.h"

#include <algorithm>
#include <cmath>

namespace k40t::sim::video {

double focal_px(Lens lens, double zoom, int width_px) {
  const LensSpec& spec = lens_spec(lens);
  return width_px * spec.focal_length_mm / spec.sensor_width_mm *
         std::clamp(zoom, 1.0, spec.max_zoom);
}

PinholeView::PinholeView(double yaw_deg, double pitch_deg, double focal_px, cv::Size size)
    : basis_(camera_basis(yaw_deg, pitch_deg)),
      pitch_deg_(pitch_deg),
      focal_px_(focal_px),
      size_(size),
      centre_((size.width - 1) / 2.0, (size.height - 1) / 2.0) {}

Vec3 PinholeView::ray(double u, double v) const {
  const double nx = (u - centre_.x) / focal_px_;
  const double ny = -(v - centre_.y) / focal_px_;
  return normalized(basis_.forward + basis_.right * nx + basis_.up * ny);
}

std::optional<cv::Point2d> PinholeView::project(const Vec3& direction) const {
  const double depth = dot(direction, basis_.forward);
  if (depth <= 1e-9) return std::nullopt;
  return cv::Point2d(centre_.x + focal_px_ * dot(direction, basis_.right) / depth,
                     centre_.y - focal_px_ * dot(direction, basis_.up) / depth);
}

double PinholeView::horizon_row() const {
  return centre_.y + focal_px_ * std::tan(deg_to_rad(pitch_deg_));
}

}  // namespace k40t::sim::video
