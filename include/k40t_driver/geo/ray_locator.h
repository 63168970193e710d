// Where a ray from the vehicle ends, on the Earth, with a covariance: the laser spot (the ray of
// the laser frame, ended at the measured range) and a pixel's ray (ended at a given range, or on
// a horizontal plane at a given height). ROS-free; the ROS glue supplies the ray in the vehicle's
// body frame from TF.
//
// Frames: the body frame is REP 103's base_link (x forward, y left, z up); the vehicle's attitude
// is in aviation angles (heading clockwise from north, nose-up pitch, right-wing-down roll),
// turned into body -> ENU as yaw = 90 deg - heading, REP 103 pitch = -pitch, roll = roll.
//
// Covariance model (docs/geo.md): independent, zero-mean errors of the vehicle position (the
// fix's ENU covariance), of each attitude angle, of the ray's direction (two angles across it:
// gimbal joint angles, boresight calibration) and of the range; propagated to the end point
// through the numerical Jacobian of the end point in the vehicle's ENU frame (central
// differences), i.e. first order.
#pragma once

#include <array>
#include <optional>

#include "k40t_driver/geo/geodesy.h"

namespace k40t::geo {

using Vector3 = std::array<double, 3>;
using Covariance3 = std::array<double, 9>;  // row-major, m^2

struct VehiclePose {
  Geodetic position;
  Covariance3 position_covariance{4, 0, 0, 0, 4, 0, 0, 0, 16};  // ENU
  double heading_deg = 0;
  double pitch_deg = 0;
  double roll_deg = 0;
};

struct BodyRay {
  Vector3 origin_m{0, 0, 0};   // in the body frame
  Vector3 direction{1, 0, 0};  // in the body frame; normalised here
};

struct RayUncertainty {
  double attitude_sigma_deg = 0.5;  // each of heading, pitch, roll
  double pointing_sigma_deg = 0.1;  // each of two angles across the ray
  double range_sigma_m = 1.0;       // of the laser; 0 for a ray ended on a plane
};

struct Located {
  Geodetic position;
  Covariance3 covariance{};  // ENU at the point, m^2
  double slant_range_m = 0;
  Enu offset;  // from the vehicle, in its ENU frame
};

// The ray ended `range_m` from its origin.
Result<Located> locate_at_range(const VehiclePose& pose, const BodyRay& ray, double range_m,
                                const RayUncertainty& uncertainty);

// The ray ended where it crosses the horizontal plane `plane_up_m` above (negative: below) the
// vehicle's position, in the vehicle's tangent frame (the Earth's curvature is ignored: at 1 km
// the ground is 8 cm below that plane). Fails when the ray does not go down to the plane (or up
// to it) or meets it beyond `max_range_m`.
Result<Located> locate_on_plane(const VehiclePose& pose, const BodyRay& ray, double plane_up_m,
                                const RayUncertainty& uncertainty, double max_range_m = 10000);

// The ray's direction in the vehicle's ENU frame.
Vector3 ray_direction_enu(const VehiclePose& pose, const BodyRay& ray);

}  // namespace k40t::geo
