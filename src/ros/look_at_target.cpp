#include "k40t_driver/ros/look_at_target.h"

#include <cmath>

#include <tf2/LinearMath/Quaternion.h>
#include <tf2/LinearMath/Vector3.h>

#include "k40t_driver/driver/vehicle_geo.h"

namespace k40t::driver {

namespace {

using k40t_driver::LookAtGoal;

constexpr double kMaxExtrapolationS = 0.5;  // older vehicle states or transforms count as this old

double norm(const geo::Vector3& v) {
  return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

}  // namespace

Result<LookAtTarget> target_of_point(const geometry_msgs::PointStamped& point) {
  if (point.header.frame_id.empty())
    return Result<LookAtTarget>::fail("the point has no frame_id (any TF frame will do)");
  if (!std::isfinite(point.point.x) || !std::isfinite(point.point.y) ||
      !std::isfinite(point.point.z))
    return Result<LookAtTarget>::fail("the point's coordinates must be finite");
  LookAtTarget target;
  target.point = point;
  return target;
}

Result<LookAtTarget> target_of_goal(const LookAtGoal& goal) {
  if (goal.target_type == LookAtGoal::TARGET_POINT) return target_of_point(goal.point);
  if (goal.target_type != LookAtGoal::TARGET_WGS84)
    return Result<LookAtTarget>::fail("target_type must be TARGET_POINT (0) or TARGET_WGS84 (1)");
  LookAtTarget target;
  target.wgs84 = true;
  target.position = {goal.latitude, goal.longitude, goal.altitude};
  if (const Status ok = geo::check_geodetic(target.position); !ok)
    return Result<LookAtTarget>::fail(ok.message());
  if (goal.altitude_datum == LookAtGoal::DATUM_MSL) {
    const Result<double> h =
        geo::Geoid::egm96().ellipsoid_from_msl(goal.latitude, goal.longitude, goal.altitude);
    if (!h) return Result<LookAtTarget>::fail("MSL altitude not converted: " + h.error());
    target.position.height_ellipsoid_m = h.value();
  } else if (goal.altitude_datum != LookAtGoal::DATUM_ELLIPSOID) {
    return Result<LookAtTarget>::fail(
        "altitude_datum must be DATUM_ELLIPSOID (0) or DATUM_MSL (1)");
  }
  return target;
}

Result<TargetInBase> TargetResolver::resolve(const LookAtTarget& target,
                                             const ros::Time& now) const {
  return target.wgs84 ? wgs84_in_base(target.position, now) : point_in_base(target.point, now);
}

Result<TargetInBase> TargetResolver::point_in_base(const geometry_msgs::PointStamped& point,
                                                   const ros::Time& now) const {
  geometry_msgs::TransformStamped t;
  try {
    t = tf_.lookupTransform(base_frame_, point.header.frame_id, ros::Time(0));
  } catch (const tf2::TransformException& e) {
    return Result<TargetInBase>::fail("no TF from " + point.header.frame_id + " to " + base_frame_ +
                                      ": " + e.what());
  }
  const tf2::Quaternion q(t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z,
                          t.transform.rotation.w);
  const tf2::Vector3 p =
      tf2::quatRotate(q, tf2::Vector3(point.point.x, point.point.y, point.point.z)) +
      tf2::Vector3(t.transform.translation.x, t.transform.translation.y, t.transform.translation.z);
  TargetInBase out;
  out.vector = {p.x(), p.y(), p.z()};
  // A static transform (stamp 0) is always current; a moving one is as old as its stamp.
  if (!t.header.stamp.isZero())
    out.age_s = std::clamp((now - t.header.stamp).toSec(), 0.0, kMaxExtrapolationS);
  return out;
}

Result<TargetInBase> TargetResolver::wgs84_in_base(const geo::Geodetic& position,
                                                   const ros::Time& now) const {
  bool in_history = true;
  double gap_s = 0;
  const VehicleState vehicle =
      driver_.vehicle_state_at(static_cast<StampNs>(now.toNSec()), &in_history, &gap_s);
  const Result<geo::VehiclePose> pose = vehicle_pose(vehicle);
  if (!pose) return Result<TargetInBase>::fail(pose.error());
  const Result<geo::Vector3> body = geo::target_in_body(pose.value(), position);
  if (!body) return Result<TargetInBase>::fail(body.error());
  TargetInBase out;
  out.vector = body.value();
  // After the newest fix the state is that fix's: as old as the gap.
  if (!in_history) out.age_s = std::clamp(gap_s, 0.0, kMaxExtrapolationS);
  if (vehicle_frame_ == base_frame_) return out;
  geometry_msgs::PointStamped in_vehicle;
  in_vehicle.header.frame_id = vehicle_frame_;
  in_vehicle.point.x = out.vector[0];
  in_vehicle.point.y = out.vector[1];
  in_vehicle.point.z = out.vector[2];
  Result<TargetInBase> moved = point_in_base(in_vehicle, now);
  if (moved) moved->age_s = out.age_s;
  return moved;
}

visualization_msgs::MarkerArray look_at_markers(const std::string& base_frame,
                                                const ros::Time& stamp, const geo::Vector3& target,
                                                const std::optional<geo::GimbalAim>& aim) {
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker m;
  m.header.frame_id = base_frame;
  m.header.stamp = stamp;
  m.ns = "look_at";
  m.action = visualization_msgs::Marker::ADD;
  m.pose.orientation.w = 1;
  m.color.a = 1;

  m.id = 0;
  m.type = visualization_msgs::Marker::SPHERE;
  const double size = std::max(1.0, norm(target) / 50);  // visible at any range
  m.scale.x = m.scale.y = m.scale.z = size;
  m.pose.position.x = target[0];
  m.pose.position.y = target[1];
  m.pose.position.z = target[2];
  m.color.r = 1;
  out.markers.push_back(m);

  m.pose.position = geometry_msgs::Point();
  m.type = visualization_msgs::Marker::LINE_LIST;
  m.scale.x = size / 5;
  m.scale.y = m.scale.z = 0;
  m.id = 1;  // line of sight
  m.color.r = 0;
  m.color.g = 1;
  m.points.resize(2);
  m.points[1].x = target[0];
  m.points[1].y = target[1];
  m.points[1].z = target[2];
  out.markers.push_back(m);
  if (aim) {
    m.id = 2;  // boresight
    m.color.r = 1;
    const geo::Vector3 b = geo::boresight(*aim);
    const double r = norm(target);
    m.points[1].x = b[0] * r;
    m.points[1].y = b[1] * r;
    m.points[1].z = b[2] * r;
    out.markers.push_back(m);
  }
  return out;
}

visualization_msgs::MarkerArray clear_look_at_markers(const std::string& base_frame) {
  visualization_msgs::MarkerArray out;
  visualization_msgs::Marker m;
  m.header.frame_id = base_frame;
  m.ns = "look_at";
  m.action = visualization_msgs::Marker::DELETEALL;
  out.markers.push_back(m);
  return out;
}

}  // namespace k40t::driver
