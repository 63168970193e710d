#include "k40t_driver/geo/ray_locator.h"

#include <cmath>
#include <functional>
#include <tuple>
#include <utility>

namespace k40t::geo {

namespace {

constexpr double kDegToRad = M_PI / 180.0;

// What the end point depends on, perturbed for the Jacobian: position (E, N, U), attitude
// (heading, pitch, roll, rad), two angles across the ray (rad), range (m).
constexpr int kParams = 9;
using Params = std::array<double, kParams>;

Vector3 normalise(const Vector3& v) {
  const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  return {v[0] / n, v[1] / n, v[2] / n};
}

Vector3 cross(const Vector3& a, const Vector3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

// Body (FLU) -> ENU: Rz(yaw) Ry(pitch) Rx(roll), REP 103 angles from the aviation ones.
Vector3 body_to_enu(const Vector3& v, double heading, double pitch, double roll) {
  const double yaw = M_PI / 2 - heading;
  const double p = -pitch;
  const double cr = std::cos(roll), sr = std::sin(roll);
  const double cp = std::cos(p), sp = std::sin(p);
  const double cy = std::cos(yaw), sy = std::sin(yaw);
  const Vector3 x{v[0], cr * v[1] - sr * v[2], sr * v[1] + cr * v[2]};   // Rx
  const Vector3 y{cp * x[0] + sp * x[2], x[1], -sp * x[0] + cp * x[2]};  // Ry
  return {cy * y[0] - sy * y[1], sy * y[0] + cy * y[1], y[2]};           // Rz
}

// Two unit vectors across the ray, for its pointing errors.
std::pair<Vector3, Vector3> across(const Vector3& d) {
  const Vector3 helper = std::abs(d[2]) < 0.9 ? Vector3{0, 0, 1} : Vector3{1, 0, 0};
  const Vector3 a = normalise(cross(d, helper));
  return {a, cross(d, a)};
}

struct Model {
  const VehiclePose& pose;
  BodyRay ray;
  Vector3 across_a, across_b;

  Model(const VehiclePose& p, const BodyRay& r) : pose(p), ray(r) {
    ray.direction = normalise(r.direction);
    std::tie(across_a, across_b) = across(ray.direction);
  }

  Vector3 direction_enu(const Params& q) const {
    Vector3 d;
    for (int i = 0; i < 3; ++i) d[i] = ray.direction[i] + q[6] * across_a[i] + q[7] * across_b[i];
    return body_to_enu(normalise(d), pose.heading_deg * kDegToRad + q[3],
                       pose.pitch_deg * kDegToRad + q[4], pose.roll_deg * kDegToRad + q[5]);
  }
  Vector3 origin_enu(const Params& q) const {
    const Vector3 o =
        body_to_enu(ray.origin_m, pose.heading_deg * kDegToRad + q[3],
                    pose.pitch_deg * kDegToRad + q[4], pose.roll_deg * kDegToRad + q[5]);
    return {o[0] + q[0], o[1] + q[1], o[2] + q[2]};
  }
};

using EndPoint = std::function<std::optional<Vector3>(const Params&)>;

// Sigma^2 of each parameter; the position block is the fix's full covariance, added apart.
Result<Covariance3> propagate(const EndPoint& end, const VehiclePose& pose,
                              const RayUncertainty& u) {
  const double att = u.attitude_sigma_deg * kDegToRad, point = u.pointing_sigma_deg * kDegToRad;
  const Params variance{0,
                        0,
                        0,
                        att * att,
                        att * att,
                        att * att,
                        point * point,
                        point * point,
                        u.range_sigma_m * u.range_sigma_m};
  const Params step{1e-3, 1e-3, 1e-3, 1e-6, 1e-6, 1e-6, 1e-6, 1e-6, 1e-3};
  std::array<Vector3, kParams> jacobian{};
  for (int k = 0; k < kParams; ++k) {
    Params plus{}, minus{};
    plus[k] = step[k];
    minus[k] = -step[k];
    const std::optional<Vector3> a = end(plus), b = end(minus);
    if (!a || !b) return Result<Covariance3>::fail("the ray grazes the plane: no covariance");
    for (int i = 0; i < 3; ++i) jacobian[k][i] = ((*a)[i] - (*b)[i]) / (2 * step[k]);
  }
  Covariance3 out{};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double sum = 0;
      for (int k = 0; k < kParams; ++k) sum += jacobian[k][i] * variance[k] * jacobian[k][j];
      for (int a = 0; a < 3; ++a) {  // the position block, with its correlations
        for (int b = 0; b < 3; ++b)
          sum += jacobian[a][i] * pose.position_covariance[a * 3 + b] * jacobian[b][j];
      }
      out[i * 3 + j] = sum;
    }
  }
  return out;
}

Result<Located> finish(const VehiclePose& pose, const EndPoint& end, const RayUncertainty& u) {
  const std::optional<Vector3> p = end(Params{});
  if (!p) return Result<Located>::fail("the ray does not reach the plane");
  const Result<LocalFrame> frame = LocalFrame::at(pose.position);
  if (!frame) return Result<Located>::fail(frame.error());
  const Result<Covariance3> covariance = propagate(end, pose, u);
  if (!covariance) return Result<Located>::fail(covariance.error());
  Located out;
  out.offset = {(*p)[0], (*p)[1], (*p)[2]};
  out.position = frame->to_geodetic(out.offset);
  out.covariance = covariance.value();
  out.slant_range_m = std::sqrt((*p)[0] * (*p)[0] + (*p)[1] * (*p)[1] + (*p)[2] * (*p)[2]);
  return out;
}

}  // namespace

Vector3 ray_direction_enu(const VehiclePose& pose, const BodyRay& ray) {
  return Model(pose, ray).direction_enu(Params{});
}

Result<Located> locate_at_range(const VehiclePose& pose, const BodyRay& ray, double range_m,
                                const RayUncertainty& u) {
  if (!std::isfinite(range_m) || range_m <= 0)
    return Result<Located>::fail("the range must be a positive number of metres");
  const Model model(pose, ray);
  const EndPoint end = [&](const Params& q) -> std::optional<Vector3> {
    const Vector3 o = model.origin_enu(q), d = model.direction_enu(q);
    const double r = range_m + q[8];
    return Vector3{o[0] + r * d[0], o[1] + r * d[1], o[2] + r * d[2]};
  };
  return finish(pose, end, u);
}

Result<Located> locate_on_plane(const VehiclePose& pose, const BodyRay& ray, double plane_up_m,
                                const RayUncertainty& u, double max_range_m) {
  const Model model(pose, ray);
  const EndPoint end = [&](const Params& q) -> std::optional<Vector3> {
    const Vector3 o = model.origin_enu(q), d = model.direction_enu(q);
    if (std::abs(d[2]) < 1e-9) return std::nullopt;
    const double t = (plane_up_m - o[2]) / d[2];
    if (t <= 0 || t > max_range_m) return std::nullopt;
    return Vector3{o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
  };
  RayUncertainty plane = u;
  plane.range_sigma_m = 0;  // no range measured
  return finish(pose, end, plane);
}

}  // namespace k40t::geo
