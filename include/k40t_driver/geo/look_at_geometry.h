// The geometry of gimbal/look_at (docs/geo.md "Looking at a place"), ROS-free: where a target is
// in the gimbal's base frame, the joint angles that point the boresight at it, whether the
// gimbal can reach them, which way the yaw turns, how far the boresight is off, and the zoom
// that keeps a ground footprint.
//
// Frames and signs: the gimbal base frame is REP 103's (x forward, y left, z up, the pod's
// k40t_base_link); angles are the pod's (0x000012, docs/protocol/gimbal_laser_sbus.md): yaw right
// positive, pitch up positive, degrees. The boresight at yaw Y, pitch P is
// (cos P cos Y, -cos P sin Y, sin P) in the base frame (the joint chain of urdf/k40t.urdf with
// roll 0: the pod takes no roll command).
#pragma once

#include "k40t_driver/geo/geodesy.h"
#include "k40t_driver/geo/ray_locator.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::geo {

struct GimbalAim {
  double yaw_deg = 0;    // right positive, -180..180
  double pitch_deg = 0;  // up positive
};

// The gimbal's reach (0x000012: pitch 30 up to 90 down, yaw 180 either way). A continuous yaw
// turns through the back (+-180 is one place); otherwise the yaw joint has end stops at
// yaw_min/yaw_max and a turn from +170 to -170 goes through 0 (the simulated pod's default,
// docs/simulator.md).
struct GimbalLimits {
  double pitch_min_deg = -90;
  double pitch_max_deg = 30;
  double yaw_min_deg = -180;
  double yaw_max_deg = 180;
  bool yaw_continuous = false;
};

// A vector of the vehicle's ENU frame in its body frame (REP 103 x forward, y left, z up), by
// the pose's aviation attitude: the inverse of ray_direction_enu().
Vector3 enu_to_body(const VehiclePose& pose, const Vector3& enu);

// The vector from the vehicle to `target` in the vehicle's body frame. Fails for positions
// check_geodetic() refuses.
Result<Vector3> target_in_body(const VehiclePose& pose, const Geodetic& target);

// The angles that point the boresight along `direction` (base frame); fails for a zero or
// non-finite vector. Straight up or down, the yaw is 0.
Result<GimbalAim> aim_along(const Vector3& direction);

// The boresight's direction (unit, base frame) at these angles.
Vector3 boresight(const GimbalAim& aim);

// Whether the gimbal can take `aim`: the reason when it cannot (above the upper limit, below the
// lower one, beyond a yaw end stop), naming the angles.
Status check_reach(const GimbalAim& aim, const GimbalLimits& limits);

// Degrees the yaw joint turns from `current_deg` to `desired_deg`, signed (right positive): the
// short way through +-180 when the yaw is continuous, otherwise the only way, inside the end
// stops.
double yaw_turn_deg(double current_deg, double desired_deg, const GimbalLimits& limits);

// `angle` wrapped into (-180, 180].
double wrap_deg(double angle);

// `target` (base frame) in the optical frame of a camera on the boresight at `aim` (z forward,
// x right, y down; the cameras' offsets from the gimbal's centre, centimetres, are left out).
Vector3 in_optical_frame(const GimbalAim& aim, const Vector3& target);

// Degrees between the boresight at `aim` and `direction` (base frame).
double pointing_error_deg(const GimbalAim& aim, const Vector3& direction);

// The width (m) across the image of what a lens whose horizontal half-angle at 1x has tangent
// `tan_half_fov_1x` covers at `zoom` at `slant_m`: 2 r tan(h / 2) / zoom (zoom scales the focal
// length, optical or digital alike).
double footprint_width_m(double slant_m, double zoom, double tan_half_fov_1x);

// The zoom that makes that width `width_m`, clamped to [min_zoom, max_zoom].
double footprint_zoom(double slant_m, double width_m, double tan_half_fov_1x, double min_zoom,
                      double max_zoom);

}  // namespace k40t::geo
