// The simulated world's geometry: a right-handed frame with x north, y east, z up, the pod at the
// origin. Angles follow the pod's reports: yaw positive to the right (clockwise seen from above,
// like a compass heading), pitch positive up. Only what the thermal scene and the laser need:
// directions, a camera's basis, and ray intersections with the ground plane, a sphere and a disc.
#pragma once

#include <cmath>
#include <optional>

namespace k40t::sim {

constexpr double kPi = 3.14159265358979323846;
inline double deg_to_rad(double deg) {
  return deg * kPi / 180.0;
}
inline double rad_to_deg(double rad) {
  return rad * 180.0 / kPi;
}
// Into (-180, 180].
double wrap_deg(double deg);

struct Vec3 {
  double x = 0;
  double y = 0;
  double z = 0;
};
inline Vec3 operator+(const Vec3& a, const Vec3& b) {
  return {a.x + b.x, a.y + b.y, a.z + b.z};
}
inline Vec3 operator-(const Vec3& a, const Vec3& b) {
  return {a.x - b.x, a.y - b.y, a.z - b.z};
}
inline Vec3 operator*(const Vec3& a, double s) {
  return {a.x * s, a.y * s, a.z * s};
}
inline double dot(const Vec3& a, const Vec3& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
inline double norm(const Vec3& a) {
  return std::sqrt(dot(a, a));
}
inline Vec3 normalized(const Vec3& a) {
  return a * (1.0 / norm(a));
}

// The unit vector of a heading (yaw) and elevation (pitch), in degrees.
Vec3 direction(double yaw_deg, double pitch_deg);

// A camera looking along `forward`, image x to `right`, image y up along `up` (no roll).
struct CameraBasis {
  Vec3 forward;
  Vec3 right;
  Vec3 up;
};
CameraBasis camera_basis(double yaw_deg, double pitch_deg);

// Three axes in the convention above, for angles and rates alike: the unit lives in the name of
// the member that holds one (joint_deg, rate_deg_s, attitude_deg).
struct YawPitchRoll {
  double yaw = 0;
  double pitch = 0;
  double roll = 0;
};

// Yaw and pitch of a direction vector, in degrees (the inverse of direction()).
double yaw_of(const Vec3& v);
double pitch_of(const Vec3& v);

// Distances along a ray (origin + t * dir, |dir| = 1) to the first hit, if any, with t > 0.
std::optional<double> hit_horizontal_plane(const Vec3& origin, const Vec3& dir, double plane_z);
std::optional<double> hit_sphere(const Vec3& origin, const Vec3& dir, const Vec3& centre,
                                 double radius);

}  // namespace k40t::sim
