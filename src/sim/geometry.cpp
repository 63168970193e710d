#include "k40t_driver/sim/geometry.h"

namespace k40t::sim {

double wrap_deg(double deg) {
  double wrapped = std::fmod(deg + 180.0, 360.0);
  if (wrapped <= 0) wrapped += 360.0;
  return wrapped - 180.0;
}

Vec3 direction(double yaw_deg, double pitch_deg) {
  const double yaw = deg_to_rad(yaw_deg);
  const double pitch = deg_to_rad(pitch_deg);
  return {std::cos(pitch) * std::cos(yaw), std::cos(pitch) * std::sin(yaw), std::sin(pitch)};
}

CameraBasis camera_basis(double yaw_deg, double pitch_deg) {
  CameraBasis basis;
  basis.forward = direction(yaw_deg, pitch_deg);
  const double yaw = deg_to_rad(yaw_deg);
  basis.right = {-std::sin(yaw), std::cos(yaw), 0.0};
  basis.up = cross(basis.forward, basis.right);
  return basis;
}

double yaw_of(const Vec3& v) {
  return rad_to_deg(std::atan2(v.y, v.x));
}
double pitch_of(const Vec3& v) {
  return rad_to_deg(std::atan2(v.z, std::hypot(v.x, v.y)));
}

std::optional<double> hit_horizontal_plane(const Vec3& origin, const Vec3& dir, double plane_z) {
  if (std::abs(dir.z) < 1e-12) return std::nullopt;
  const double t = (plane_z - origin.z) / dir.z;
  if (t <= 0) return std::nullopt;
  return t;
}

std::optional<double> hit_sphere(const Vec3& origin, const Vec3& dir, const Vec3& centre,
                                 double radius) {
  const Vec3 oc = origin - centre;
  const double b = dot(oc, dir);
  const double c = dot(oc, oc) - radius * radius;
  const double discriminant = b * b - c;
  if (discriminant < 0) return std::nullopt;
  const double root = std::sqrt(discriminant);
  const double near = -b - root;
  if (near > 0) return near;
  const double far = -b + root;  // origin inside the sphere
  if (far > 0) return far;
  return std::nullopt;
}

}  // namespace k40t::sim
