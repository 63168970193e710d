#include "k40t_driver/geo/geodesy.h"

#include <cmath>

#include <GeographicLib/Geocentric.hpp>
#include <GeographicLib/LocalCartesian.hpp>

namespace k40t::geo {

Status check_geodetic(const Geodetic& point) {
  if (!std::isfinite(point.latitude_deg) || std::abs(point.latitude_deg) > 90.0)
    return Status::fail("latitude must be a finite number of degrees in [-90, 90]");
  if (!std::isfinite(point.longitude_deg)) return Status::fail("longitude must be finite");
  if (!std::isfinite(point.height_ellipsoid_m)) return Status::fail("height must be finite");
  return Status::ok();
}

Result<Ecef> to_ecef(const Geodetic& point) {
  const Status valid = check_geodetic(point);
  if (!valid) return Result<Ecef>::fail(valid.message());
  Ecef out;
  GeographicLib::Geocentric::WGS84().Forward(point.latitude_deg, point.longitude_deg,
                                             point.height_ellipsoid_m, out.x, out.y, out.z);
  return out;
}

Geodetic from_ecef(const Ecef& point) {
  Geodetic out;
  GeographicLib::Geocentric::WGS84().Reverse(point.x, point.y, point.z, out.latitude_deg,
                                             out.longitude_deg, out.height_ellipsoid_m);
  return out;
}

Result<LocalFrame> LocalFrame::at(const Geodetic& origin) {
  const Status valid = check_geodetic(origin);
  if (!valid) return Result<LocalFrame>::fail(valid.message());
  return LocalFrame(origin);
}

// GeographicLib::LocalCartesian is cheap to build (a rotation matrix and the origin's ECEF), so
// one per call keeps LocalFrame a plain copyable value.
Enu LocalFrame::to_enu(const Geodetic& point) const {
  const GeographicLib::LocalCartesian frame(origin_.latitude_deg, origin_.longitude_deg,
                                            origin_.height_ellipsoid_m);
  Enu out;
  frame.Forward(point.latitude_deg, point.longitude_deg, point.height_ellipsoid_m, out.east,
                out.north, out.up);
  return out;
}

Geodetic LocalFrame::to_geodetic(const Enu& point) const {
  const GeographicLib::LocalCartesian frame(origin_.latitude_deg, origin_.longitude_deg,
                                            origin_.height_ellipsoid_m);
  Geodetic out;
  frame.Reverse(point.east, point.north, point.up, out.latitude_deg, out.longitude_deg,
                out.height_ellipsoid_m);
  return out;
}

double distance_m(const Geodetic& a, const Geodetic& b) {
  const Result<LocalFrame> frame = LocalFrame::at(a);
  if (!frame) return std::nan("");
  const Enu d = frame->to_enu(b);
  return std::sqrt(d.east * d.east + d.north * d.north + d.up * d.up);
}

}  // namespace k40t::geo
