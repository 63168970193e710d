#include "demo_scene.h"

#include <cmath>

namespace k40t::tools {

namespace {
constexpr double kCameraHeightM = 30;

// Temperature of a round patch of `radius_m` at (north, east): `peak` at the centre, fading out.
double patch(double north, double east, double centre_n, double centre_e, double radius_m,
             double peak) {
  const double d2 = (north - centre_n) * (north - centre_n) + (east - centre_e) * (east - centre_e);
  return peak * std::exp(-d2 / (radius_m * radius_m));
}
}  // namespace

double demo_scene_temperature(const sim::video::WorldDirection& d) {
  if (d.up >= -1e-3) return -35 + 25 * (1 - d.up);  // sky: -10 at the horizon, -35 overhead
  const double t = kCameraHeightM / -d.up;          // where the ray meets the ground
  const double north = d.north * t;
  const double east = d.east * t;
  return 20 + 2.5 * std::sin(north / 7) * std::cos(east / 5) + patch(north, east, 80, 20, 3, 65) -
         patch(north, east, 60, -30, 8, 18);
}

}  // namespace k40t::tools
