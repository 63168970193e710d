#include "k40t_driver/geo/body_velocity.h"

#include <cmath>

namespace k40t::geo {

Result<VelocitySample> enu_velocity_from_body(const Orientation& q, double forward, double left,
                                              double up) {
  const double norm = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
  if (!std::isfinite(norm) || !std::isfinite(forward) || !std::isfinite(left) || !std::isfinite(up))
    return Result<VelocitySample>::fail("odometry ignored: a number is not finite");
  if (norm < 1e-6)
    return Result<VelocitySample>::fail(
        "odometry ignored: its orientation is a zero quaternion (unknown), so its body-frame "
        "twist cannot be turned into east-north-up");
  const double x = q.x / norm, y = q.y / norm, z = q.z / norm, w = q.w / norm;
  // v' = v + 2w (u x v) + 2 u x (u x v), u = (x, y, z): the rotation of v by the unit quaternion.
  const double v[3] = {forward, left, up};
  const double t[3] = {2 * (y * v[2] - z * v[1]), 2 * (z * v[0] - x * v[2]),
                       2 * (x * v[1] - y * v[0])};
  VelocitySample out;
  out.east = v[0] + w * t[0] + (y * t[2] - z * t[1]);
  out.north = v[1] + w * t[1] + (z * t[0] - x * t[2]);
  out.up = v[2] + w * t[2] + (x * t[1] - y * t[0]);
  return out;
}

}  // namespace k40t::geo
