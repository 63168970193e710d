// Small-offset metres from degrees on the WGS 84 ellipsoid, written out from the radii of
// curvature (not through geo/geodesy.h, whose results the tests check): a meridian degree is
// (M + h) pi/180 and a parallel degree (N + h) cos(lat) pi/180, with
// M = a (1 - e^2) / w^3, N = a / w, w = sqrt(1 - e^2 sin^2 lat).
#pragma once

#include <cmath>

namespace k40t::test {

struct Wgs84Radii {
  double meridian_m;
  double prime_vertical_m;
};

inline Wgs84Radii wgs84_radii(double latitude_deg) {
  constexpr double kA = 6378137.0, kF = 1.0 / 298.257223563;
  const double e2 = kF * (2 - kF);
  const double s = std::sin(latitude_deg * M_PI / 180);
  const double w = std::sqrt(1 - e2 * s * s);
  return {kA * (1 - e2) / (w * w * w), kA / w};
}

// Metres north of latitude `from_deg` at height `h_m` (offsets of a few hundred metres).
inline double metres_north(double from_deg, double to_deg, double h_m) {
  return (to_deg - from_deg) * M_PI / 180 * (wgs84_radii(from_deg).meridian_m + h_m);
}
inline double metres_east(double latitude_deg, double from_deg, double to_deg, double h_m) {
  return (to_deg - from_deg) * M_PI / 180 * (wgs84_radii(latitude_deg).prime_vertical_m + h_m) *
         std::cos(latitude_deg * M_PI / 180);
}

}  // namespace k40t::test
