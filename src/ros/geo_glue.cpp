#include "k40t_driver/ros/geo_glue.h"

#include <algorithm>
#include <cmath>

#include <tf2/LinearMath/Quaternion.h>
#include <tf2/LinearMath/Vector3.h>

namespace k40t::driver {

Result<geo::BodyRay> ray_in_vehicle(const tf2_ros::Buffer& tf, const std::string& vehicle_frame,
                                    const std::string& sensor_frame, const ros::Time& stamp,
                                    const geo::Vector3& direction) {
  geometry_msgs::TransformStamped t;
  try {
    t = tf.canTransform(vehicle_frame, sensor_frame, stamp)
            ? tf.lookupTransform(vehicle_frame, sensor_frame, stamp)
            : tf.lookupTransform(vehicle_frame, sensor_frame, ros::Time(0));
  } catch (const tf2::TransformException& e) {
    return Result<geo::BodyRay>::fail("no TF from " + vehicle_frame + " to " + sensor_frame + ": " +
                                      e.what());
  }
  const tf2::Quaternion q(t.transform.rotation.x, t.transform.rotation.y, t.transform.rotation.z,
                          t.transform.rotation.w);
  const tf2::Vector3 d = tf2::quatRotate(q, tf2::Vector3(direction[0], direction[1], direction[2]));
  geo::BodyRay ray;
  ray.origin_m = {t.transform.translation.x, t.transform.translation.y, t.transform.translation.z};
  ray.direction = {d.x(), d.y(), d.z()};
  return ray;
}

sensor_msgs::NavSatFix to_nav_sat_fix(const geo::Located& located, const ros::Time& stamp,
                                      const std::string& frame_id) {
  sensor_msgs::NavSatFix fix;
  fix.header.stamp = stamp;
  fix.header.frame_id = frame_id;
  fix.status.status = sensor_msgs::NavSatStatus::STATUS_FIX;
  fix.status.service = sensor_msgs::NavSatStatus::SERVICE_GPS;
  fix.latitude = located.position.latitude_deg;
  fix.longitude = located.position.longitude_deg;
  fix.altitude = located.position.height_ellipsoid_m;
  for (size_t i = 0; i < 9; ++i) fix.position_covariance[i] = located.covariance[i];
  fix.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_KNOWN;
  return fix;
}

k40t_driver::LaserTarget to_laser_target(const protocol::TargetGpsAck& target,
                                         const ros::Time& stamp, const std::string& frame_id,
                                         const VehicleState& vehicle,
                                         protocol::LaserTargetZeros zeros) {
  k40t_driver::LaserTarget report;
  report.header.stamp = stamp;
  report.header.frame_id = frame_id;
  report.code = static_cast<uint16_t>(target.code);
  report.mount_mask = target.mount_mask;
  report.pod_utc.fromNSec(target.utc_time_ms * 1000000);
  report.latitude = target.latitude_deg;
  report.longitude = target.longitude_deg;
  report.relative_height = target.relative_height_m;
  report.altitude_msl = target.altitude_m;
  report.position_covariance.fill(-1.0);
  // A no-return's zeros are no place: 0 deg, 0 deg would get the geoid's 17 m there and, from a
  // vehicle thousands of km away, a covariance of 1e9 m^2 (which replay, without the vehicle,
  // could not regenerate).
  if (protocol::laser_target_no_return(target, zeros)) {
    report.altitude = std::nan("");
    return report;
  }
  const Result<double> h = geo::Geoid::egm96().ellipsoid_from_msl(
      target.latitude_deg, target.longitude_deg, target.altitude_m);
  report.altitude = h ? h.value() : std::nan("");
  if (target.code != protocol::ResponseCode::kOk || !h) return report;
  const std::optional<geo::Covariance3> covariance =
      laser_target_covariance({target.latitude_deg, target.longitude_deg, h.value()}, vehicle);
  if (covariance)
    std::copy(covariance->begin(), covariance->end(), report.position_covariance.begin());
  return report;
}

geo::RayUncertainty read_uncertainty(const ros::NodeHandle& private_nh) {
  geo::RayUncertainty u;
  private_nh.param("attitude_sigma", u.attitude_sigma_deg, u.attitude_sigma_deg);
  private_nh.param("pointing_sigma", u.pointing_sigma_deg, u.pointing_sigma_deg);
  private_nh.param("range_sigma", u.range_sigma_m, u.range_sigma_m);
  auto sane = [](double& v, double fallback) {
    if (!std::isfinite(v) || v < 0) v = fallback;
  };
  const geo::RayUncertainty defaults;
  sane(u.attitude_sigma_deg, defaults.attitude_sigma_deg);
  sane(u.pointing_sigma_deg, defaults.pointing_sigma_deg);
  sane(u.range_sigma_m, defaults.range_sigma_m);
  return u;
}

}  // namespace k40t::driver
