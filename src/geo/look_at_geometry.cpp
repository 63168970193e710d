#include "k40t_driver/geo/look_at_geometry.h"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace k40t::geo {

namespace {
constexpr double kDegToRad = M_PI / 180.0;
constexpr double kRadToDeg = 180.0 / M_PI;

double norm(const Vector3& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

std::string degrees(double value) {
  std::ostringstream out;
  out.precision(1);
  out << std::fixed << value << " deg";
  return out.str();
}
}  // namespace

Vector3 enu_to_body(const VehiclePose& pose, const Vector3& v) {
  // body -> ENU is Rz(yaw) Ry(pitch) Rx(roll) with REP 103 angles (ray_locator.cpp); its inverse
  // applies Rz(-yaw), then Ry(-pitch), then Rx(-roll).
  const double yaw = (90.0 - pose.heading_deg) * kDegToRad;
  const double pitch = -pose.pitch_deg * kDegToRad;
  const double roll = pose.roll_deg * kDegToRad;
  const double cy = std::cos(yaw), sy = std::sin(yaw);
  const double cp = std::cos(pitch), sp = std::sin(pitch);
  const double cr = std::cos(roll), sr = std::sin(roll);
  const Vector3 z{cy * v[0] + sy * v[1], -sy * v[0] + cy * v[1], v[2]};
  const Vector3 y{cp * z[0] - sp * z[2], z[1], sp * z[0] + cp * z[2]};
  return {y[0], cr * y[1] + sr * y[2], -sr * y[1] + cr * y[2]};
}

Result<Vector3> target_in_body(const VehiclePose& pose, const Geodetic& target) {
  if (const Status ok = check_geodetic(target); !ok) return Result<Vector3>::fail(ok.message());
  const Result<LocalFrame> frame = LocalFrame::at(pose.position);
  if (!frame) return Result<Vector3>::fail(frame.error());
  const Enu enu = frame->to_enu(target);
  return enu_to_body(pose, {enu.east, enu.north, enu.up});
}

Result<GimbalAim> aim_along(const Vector3& d) {
  const double n = norm(d);
  if (!std::isfinite(n) || n == 0.0)
    return Result<GimbalAim>::fail("the target is at the gimbal or not a finite point");
  GimbalAim aim;
  const double horizontal = std::hypot(d[0], d[1]);
  aim.yaw_deg = horizontal > 0 ? wrap_deg(-std::atan2(d[1], d[0]) * kRadToDeg) : 0.0;
  aim.pitch_deg = std::atan2(d[2], horizontal) * kRadToDeg;
  return aim;
}

Vector3 boresight(const GimbalAim& aim) {
  const double y = aim.yaw_deg * kDegToRad, p = aim.pitch_deg * kDegToRad;
  return {std::cos(p) * std::cos(y), -std::cos(p) * std::sin(y), std::sin(p)};
}

Vector3 in_optical_frame(const GimbalAim& aim, const Vector3& t) {
  const double y = aim.yaw_deg * kDegToRad;
  const Vector3 f = boresight(aim);
  const Vector3 r{-std::sin(y), -std::cos(y), 0};  // right: base -y turned by the yaw
  const Vector3 d{f[1] * r[2] - f[2] * r[1], f[2] * r[0] - f[0] * r[2],
                  f[0] * r[1] - f[1] * r[0]};  // down = forward x right
  const auto dot = [&t](const Vector3& a) { return a[0] * t[0] + a[1] * t[1] + a[2] * t[2]; };
  return {dot(r), dot(d), dot(f)};
}

Status check_reach(const GimbalAim& aim, const GimbalLimits& limits) {
  if (aim.pitch_deg > limits.pitch_max_deg)
    return Status::fail("the target is " + degrees(aim.pitch_deg) +
                        " up, above the gimbal's upper limit (" + degrees(limits.pitch_max_deg) +
                        " up)");
  if (aim.pitch_deg < limits.pitch_min_deg)
    return Status::fail("the target is " + degrees(-aim.pitch_deg) +
                        " down, below the gimbal's lower limit (" + degrees(-limits.pitch_min_deg) +
                        " down)");
  if (!limits.yaw_continuous &&
      (aim.yaw_deg < limits.yaw_min_deg || aim.yaw_deg > limits.yaw_max_deg))
    return Status::fail("the target is at yaw " + degrees(aim.yaw_deg) +
                        ", beyond the gimbal's yaw end stops (" + degrees(limits.yaw_min_deg) +
                        " .. " + degrees(limits.yaw_max_deg) + ")");
  return Status::ok();
}

double wrap_deg(double angle) {
  double wrapped = std::fmod(angle, 360.0);
  if (wrapped <= -180.0) wrapped += 360.0;
  if (wrapped > 180.0) wrapped -= 360.0;
  return wrapped;
}

double yaw_turn_deg(double current_deg, double desired_deg, const GimbalLimits& limits) {
  if (limits.yaw_continuous) return wrap_deg(desired_deg - current_deg);
  return std::clamp(desired_deg, limits.yaw_min_deg, limits.yaw_max_deg) - current_deg;
}

double pointing_error_deg(const GimbalAim& aim, const Vector3& direction) {
  const double n = norm(direction);
  if (!std::isfinite(n) || n == 0.0) return std::nan("");
  const Vector3 b = boresight(aim);
  const double cosine = (b[0] * direction[0] + b[1] * direction[1] + b[2] * direction[2]) / n;
  const Vector3 c{b[1] * direction[2] - b[2] * direction[1],
                  b[2] * direction[0] - b[0] * direction[2],
                  b[0] * direction[1] - b[1] * direction[0]};
  // atan2 of sine and cosine: exact near 0, where acos loses half the digits.
  return std::atan2(norm(c) / n, cosine) * kRadToDeg;
}

double footprint_width_m(double slant_m, double zoom, double tan_half_fov_1x) {
  return 2.0 * slant_m * tan_half_fov_1x / zoom;
}

double footprint_zoom(double slant_m, double width_m, double tan_half_fov_1x, double min_zoom,
                      double max_zoom) {
  return std::clamp(2.0 * slant_m * tan_half_fov_1x / width_m, min_zoom, max_zoom);
}

}  // namespace k40t::geo
