#include "k40t_driver/sim/world.h"

#include <algorithm>
#include <cmath>

#include "k40t_driver/codec/enum_names.h"

namespace k40t::sim {

const char* to_string(Surface surface) {
  static constexpr EnumName<Surface> kNames[] = {{Surface::kSky, "sky"},
                                                 {Surface::kGround, "ground"},
                                                 {Surface::kHotObject, "hot object"},
                                                 {Surface::kColdObject, "cold object"}};
  return name_in(kNames, surface);
}

Vec3 World::hot_object_centre() const {
  return {config_.hot.north_m - pod_north_m_, config_.hot.east_m - pod_east_m_,
          -config_.ground_height_m + config_.hot.radius_m};
}

Vec3 World::cold_object_centre() const {
  return {config_.cold.north_m - pod_north_m_, config_.cold.east_m - pod_east_m_,
          -config_.ground_height_m};
}

// At a point relative to the pod; the pattern is fixed to the ground.
double World::ground_temperature(double north_m, double east_m) const {
  north_m += pod_north_m_;
  east_m += pod_east_m_;
  return config_.ground_temperature_degC +
         config_.ground_texture_degC * std::sin(north_m / 37.0) * std::cos(east_m / 23.0);
}

Hit World::trace(const Vec3& dir) const {
  const Vec3 origin{};
  Hit hit;
  const std::optional<double> sphere =
      hit_sphere(origin, dir, hot_object_centre(), config_.hot.radius_m);
  const std::optional<double> ground = hit_horizontal_plane(origin, dir, -config_.ground_height_m);

  if (sphere && (!ground || *sphere <= *ground)) {
    // Hottest where the surface faces the viewer, falling to ground temperature at the limb.
    const Vec3 point = dir * *sphere;
    const Vec3 outward = normalized(point - hot_object_centre());
    const double facing = std::max(0.0, -dot(outward, dir));
    const double rim = ground_temperature(point.x, point.y);
    hit.surface = Surface::kHotObject;
    hit.distance_m = *sphere;
    hit.temperature_degC = rim + (config_.hot.temperature_degC - rim) * std::sqrt(facing);
    return hit;
  }
  if (ground) {
    const Vec3 point = dir * *ground;
    const double ground_degC = ground_temperature(point.x, point.y);
    const Vec3 pond = cold_object_centre();
    const double from_pond = std::hypot(point.x - pond.x, point.y - pond.y);
    hit.distance_m = *ground;
    if (from_pond < config_.cold.radius_m) {
      // Coldest at the centre, blending smoothly into the ground at the rim.
      const double r = from_pond / config_.cold.radius_m;
      const double blend = r * r * (3 - 2 * r);
      hit.surface = Surface::kColdObject;
      hit.temperature_degC =
          config_.cold.temperature_degC + (ground_degC - config_.cold.temperature_degC) * blend;
    } else {
      hit.surface = Surface::kGround;
      hit.temperature_degC = ground_degC;
    }
    return hit;
  }
  const double elevation_deg = std::max(0.0, pitch_of(dir));
  hit.temperature_degC =
      config_.sky_zenith_degC +
      (config_.sky_horizon_degC - config_.sky_zenith_degC) * std::exp(-elevation_deg / 10.0);
  return hit;
}

}  // namespace k40t::sim
