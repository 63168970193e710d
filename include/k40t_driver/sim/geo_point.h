// A position as the pod's protocol carries it (0x000310's answer, 0x000320's request and reply):
// WGS 84 latitude and longitude with two heights, so both the host's fix and the laser target
// are one type.
#pragma once

namespace k40t::sim {

struct GeoPoint {
  double latitude_deg = 0;
  double longitude_deg = 0;
  double relative_height_m = 0;  // above the take-off point
  double altitude_m = 0;         // above mean sea level (EGM96 geoid)
};

}  // namespace k40t::sim
