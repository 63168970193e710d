#include "k40t_driver/sim/laser_model.h"

#include "k40t_driver/geo/geodesy.h"

namespace k40t::sim {

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
  // The pod's height is above sea level; the ENU frame wants the ellipsoid's.
  const geo::Geoid& geoid = geo::Geoid::egm96();
  const Result<double> pod_h =
      geoid.ellipsoid_from_msl(pod.latitude_deg, pod.longitude_deg, pod.altitude_m);
  if (!pod_h) return std::nullopt;
  const Result<geo::LocalFrame> frame =
      geo::LocalFrame::at({pod.latitude_deg, pod.longitude_deg, pod_h.value()});
  if (!frame) return std::nullopt;
  const geo::Geodetic spot = frame->to_geodetic({offset.y, offset.x, offset.z});
  const Result<double> spot_msl =
      geoid.msl_from_ellipsoid(spot.latitude_deg, spot.longitude_deg, spot.height_ellipsoid_m);
  if (!spot_msl) return std::nullopt;
  GeoPoint target;
  target.latitude_deg = spot.latitude_deg;
  target.longitude_deg = spot.longitude_deg;
  target.altitude_m = spot_msl.value();
  target.relative_height_m = pod.relative_height_m + (target.altitude_m - pod.altitude_m);
  return target;
}

}  // namespace k40t::sim
