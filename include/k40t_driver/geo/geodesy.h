// Geodesy for the simulator and the driver alike, from Debian's libraries rather than by hand:
//   - GeographicLib: WGS 84 geodetic <-> ECEF <-> a local east-north-up (ENU) tangent frame;
//   - PROJ with proj-data's EGM96 grid (egm96_15.gtx): heights above the WGS 84 ellipsoid <->
//     heights above mean sea level (the EGM96 geoid), h = H + N.
// Datums used everywhere in this package (docs/geo.md):
//   *_ellipsoid_m  above the WGS 84 ellipsoid (GPS receivers, sensor_msgs/NavSatFix.altitude);
//   *_msl_m        above mean sea level, the EGM96 geoid (the pod's 海拔高度 fields).
// ROS-free and exception-free: GeographicLib's exceptions (latitude beyond +-90) are checked for
// before the call and reported as a failed Result.
#pragma once

#include <array>
#include <memory>

#include "k40t_driver/protocol/result.h"

namespace k40t::geo {

// A WGS 84 position; the height is above the ellipsoid.
struct Geodetic {
  double latitude_deg = 0;
  double longitude_deg = 0;
  double height_ellipsoid_m = 0;
};

// Metres in a local tangent frame: x east, y north, z up (REP 103's ENU).
struct Enu {
  double east = 0;
  double north = 0;
  double up = 0;
};

// Earth-centred, earth-fixed WGS 84 coordinates, metres.
struct Ecef {
  double x = 0;
  double y = 0;
  double z = 0;
};

// A position with a finite latitude in [-90, 90] and a finite longitude and height.
Status check_geodetic(const Geodetic& point);

Result<Ecef> to_ecef(const Geodetic& point);
Geodetic from_ecef(const Ecef& point);

// The ENU frame tangent to the ellipsoid at `origin`. Exact (no flat-earth approximation) at any
// distance; the frame's axes are those of the origin.
class LocalFrame {
 public:
  // Fails for an origin check_geodetic() refuses.
  static Result<LocalFrame> at(const Geodetic& origin);

  const Geodetic& origin() const { return origin_; }
  Enu to_enu(const Geodetic& point) const;
  Geodetic to_geodetic(const Enu& point) const;

 private:
  explicit LocalFrame(const Geodetic& origin) : origin_(origin) {}
  Geodetic origin_;
};

// Straight-line metres between two positions (through the Earth, not along it); NaN when `a` is
// not a position check_geodetic() accepts.
double distance_m(const Geodetic& a, const Geodetic& b);

// The EGM96 geoid through PROJ (grid egm96_15.gtx of proj-data). One shared instance, thread-safe.
class Geoid {
 public:
  // The process-wide EGM96 geoid; its load error (missing grid, PROJ failure) is reported by
  // every call.
  static const Geoid& egm96();
  ~Geoid();
  Geoid(const Geoid&) = delete;
  Geoid& operator=(const Geoid&) = delete;

  // The geoid undulation N: the geoid's height above the ellipsoid at that place, metres.
  Result<double> undulation_m(double latitude_deg, double longitude_deg) const;
  // H = h - N and h = H + N.
  Result<double> msl_from_ellipsoid(double latitude_deg, double longitude_deg,
                                    double height_ellipsoid_m) const;
  Result<double> ellipsoid_from_msl(double latitude_deg, double longitude_deg,
                                    double height_msl_m) const;

 private:
  explicit Geoid(const char* grid);
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace k40t::geo
