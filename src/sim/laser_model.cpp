#include "k40t_driver/sim/laser_model.h"

#include <cmath>

namespace k40t::sim {

namespace {
constexpr double kEarthRadiusM = 6378137.0;  // WGS-84 equatorial radius
}

std::optional<double> LaserModel::range(const World& world, double yaw_deg,
                                        double pitch_deg) const {
  const Hit hit = world.trace(direction(yaw_deg, pitch_deg));
  if (!hit.distance_m || *hit.distance_m > config_.max_range_m) return std::nullopt;
  return hit.distance_m;
}

std::optional<GeoPoint> LaserModel::locate_target(const World& world, const GeoPoint& pod,
                                                  double yaw_deg, double pitch_deg) const {
  const std::optional<double> distance = range(world, yaw_deg, pitch_deg);
  if (!distance) return std::nullopt;
  const Vec3 offset = direction(yaw_deg, pitch_deg) * *distance;  // north, east, up
  GeoPoint target;
  target.latitude_deg = pod.latitude_deg + rad_to_deg(offset.x / kEarthRadiusM);
  target.longitude_deg =
      pod.longitude_deg +
      rad_to_deg(offset.y / (kEarthRadiusM * std::cos(deg_to_rad(pod.latitude_deg))));
  target.relative_height_m = pod.relative_height_m + offset.z;
  target.altitude_m = pod.altitude_m + offset.z;
  return target;
}

}  // namespace k40t::sim
