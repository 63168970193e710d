#include "k40t_driver/ros/conversions.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <tf2/LinearMath/Quaternion.h>

#include "k40t_driver/driver/code_text.h"
#include "k40t_driver/geo/geodesy.h"

namespace k40t::driver {

namespace {

std_msgs::Header header(const ros::Time& stamp, const std::string& frame_id = "") {
  std_msgs::Header h;
  h.stamp = stamp;
  h.frame_id = frame_id;
  return h;
}

geometry_msgs::Quaternion to_quaternion(const Rep103Angles& a) {
  tf2::Quaternion q;
  q.setRPY(a.roll, a.pitch, a.yaw);  // R = Rz(yaw) Ry(pitch) Rx(roll)
  geometry_msgs::Quaternion out;
  out.x = q.x();
  out.y = q.y();
  out.z = q.z();
  out.w = q.w();
  return out;
}

geometry_msgs::TransformStamped transform(const ros::Time& stamp, const std::string& parent,
                                          const std::string& child,
                                          const std::array<double, 3>& xyz,
                                          const Rep103Angles& rotation) {
  geometry_msgs::TransformStamped t;
  t.header = header(stamp, parent);
  t.child_frame_id = child;
  t.transform.translation.x = xyz[0];
  t.transform.translation.y = xyz[1];
  t.transform.translation.z = xyz[2];
  t.transform.rotation = to_quaternion(rotation);
  return t;
}

// x forward -> z forward, x right, y down (REP 103 camera optical frame).
const Rep103Angles kOptical{-M_PI / 2, -M_PI / 2, 0};

}  // namespace

sensor_msgs::JointState to_joint_state(const protocol::GimbalAttitude& attitude,
                                       const ros::Time& stamp, const FrameIds& ids) {
  const Rep103Angles position =
      rep103_from_pod(attitude.joint_yaw_deg, attitude.joint_roll_deg, attitude.joint_pitch_deg);
  const Rep103Angles velocity =
      rep103_from_pod(attitude.yaw_rate_deg_s, attitude.roll_rate_deg_s, attitude.pitch_rate_deg_s);
  sensor_msgs::JointState js;
  js.header = header(stamp);
  js.name = {ids.yaw_joint, ids.roll_joint, ids.pitch_joint};
  js.position = {position.yaw, position.roll, position.pitch};
  js.velocity = {velocity.yaw, velocity.roll, velocity.pitch};
  return js;
}

geometry_msgs::QuaternionStamped to_attitude(const protocol::GimbalAttitude& attitude,
                                             const ros::Time& stamp, const FrameIds& ids,
                                             protocol::AttitudeOrder order) {
  geometry_msgs::QuaternionStamped q;
  q.header = header(stamp, ids.level);
  const Quaternion r = attitude_rotation(
      rep103_from_pod(attitude.yaw_deg, attitude.roll_deg, attitude.pitch_deg), order);
  q.quaternion.x = r.x;
  q.quaternion.y = r.y;
  q.quaternion.z = r.z;
  q.quaternion.w = r.w;
  return q;
}

std::vector<geometry_msgs::TransformStamped> gimbal_transforms(
    const protocol::GimbalAttitude& attitude, const ros::Time& stamp, const FrameIds& ids,
    const GimbalGeometry& geometry) {
  const Rep103Angles joints =
      rep103_from_pod(attitude.joint_yaw_deg, attitude.joint_roll_deg, attitude.joint_pitch_deg);
  return {transform(stamp, ids.base, ids.yaw, geometry.yaw_joint, {joints.yaw, 0, 0}),
          transform(stamp, ids.yaw, ids.roll, geometry.roll_joint, {0, joints.roll, 0}),
          transform(stamp, ids.roll, ids.pitch, geometry.pitch_joint, {0, 0, joints.pitch})};
}

std::vector<geometry_msgs::TransformStamped> sensor_transforms(const ros::Time& stamp,
                                                               const FrameIds& ids,
                                                               const GimbalGeometry& geometry) {
  return {transform(stamp, ids.pitch, ids.tele, geometry.tele, kOptical),
          transform(stamp, ids.pitch, ids.wide, geometry.wide, kOptical),
          transform(stamp, ids.pitch, ids.thermal, geometry.thermal, kOptical),
          transform(stamp, ids.pitch, ids.laser, geometry.laser, Rep103Angles{})};
}

k40t_driver::GimbalStatus to_msg(const protocol::GimbalStatus& status, const ros::Time& stamp) {
  k40t_driver::GimbalStatus m;
  m.header = header(stamp);
  m.gimbal_link_ok = status.gimbal_link == protocol::GimbalLinkState::kNormal;
  m.camera_link_ok = status.camera_link == protocol::GimbalLinkState::kNormal;
  m.upgrade_state = code_of(status.upgrade);
  m.thermal_ok = status.ir_ok;
  m.tele_ok = status.tele_ok;
  m.wide_ok = status.wide_ok;
  m.laser_ok = status.laser_ok;
  m.stabilisation = code_of(status.stabilisation);
  m.stabilisation_text = text_of(status.stabilisation);
  return m;
}

k40t_driver::CameraStatus to_msg(const protocol::CameraSystemStatus& status,
                                 const ros::Time& stamp) {
  static constexpr float kBitrateMbps[] = {0.0f, 1.0f, 1.5f, 2.0f, 4.0f, 8.0f, 12.0f};
  k40t_driver::CameraStatus m;
  m.header = header(stamp);
  m.mode = code_of(status.capture_mode);
  m.stream_resolution = code_of(status.stream_resolution);
  m.stream_encoding = code_of(status.encoding);
  m.image_mode = code_of(status.image_mode);
  m.stream_bitrate_code = code_of(status.bitrate);
  m.stream_bitrate_mbps = m.stream_bitrate_code <= 6 ? kBitrateMbps[m.stream_bitrate_code] : 0.0f;
  m.photo_mode = code_of(status.photo_mode);
  m.timelapse_interval_s = status.time_lapse_interval_s;
  m.burst_count = status.burst_count;
  m.sd_state = code_of(status.sd_state);
  m.sd_state_text = text_of(status.sd_state);
  m.sd_total_mb = static_cast<float>(status.sd_total_mb);
  m.sd_free_mb = static_cast<float>(status.sd_free_mb);
  m.sd_used_mb = static_cast<float>(status.sd_used_mb);
  return m;
}

k40t_driver::VisibleStatus to_msg(const protocol::VisibleStatus& status, const ros::Time& stamp) {
  k40t_driver::VisibleStatus m;
  m.header = header(stamp);
  m.zooming = status.zooming;
  m.focal_length_mm = static_cast<float>(status.focal_length_mm);
  m.zoom_ratio = static_cast<float>(status.zoom_x);
  m.ev_code = code_of(status.ev);
  switch (status.ev) {
    case protocol::ExposureValue::kPlus2:
      m.ev = 2.0f;
      break;
    case protocol::ExposureValue::kPlus1:
      m.ev = 1.0f;
      break;
    case protocol::ExposureValue::kZero:
      m.ev = 0.0f;
      break;
    case protocol::ExposureValue::kMinus1:
      m.ev = -1.0f;
      break;
    case protocol::ExposureValue::kMinus2:
      m.ev = -2.0f;
      break;
    default:
      m.ev = std::numeric_limits<float>::quiet_NaN();
      break;  // auto or undocumented
  }
  m.iso_gain_db = static_cast<float>(status.iso_db);
  m.shutter_s = static_cast<float>(status.shutter_us * 1e-6);
  m.ae_locked = status.ae_lock_on;
  m.focusing = status.focusing;
  m.precise_shot_focal_length_mm = static_cast<float>(status.precise_shot_focal_length_mm);
  return m;
}

k40t_driver::ThermalStats to_msg(const protocol::ThermalStatus& status, const ros::Time& stamp,
                                 const FrameIds& ids) {
  k40t_driver::ThermalStats m;
  m.header = header(stamp, ids.thermal);
  m.max_degC = static_cast<float>(status.max_degC);
  m.min_degC = static_cast<float>(status.min_degC);
  m.centre_degC = static_cast<float>(status.center_degC);
  m.average_degC = static_cast<float>(status.average_degC);
  m.max_x = status.max_x_px;
  m.max_y = status.max_y_px;
  m.min_x = status.min_x_px;
  m.min_y = status.min_y_px;
  m.centre_x = status.center_x_px;
  m.centre_y = status.center_y_px;
  m.point_degC = static_cast<float>(status.point_degC);
  m.point_x = status.point_x_px;
  m.point_y = status.point_y_px;
  m.high_alarm = status.high_alarm;
  m.low_alarm = status.low_alarm;
  m.difference_alarm = status.difference_alarm;
  m.threshold_alarm = status.threshold_alarm;
  return m;
}

// Photo and record status frames share their first two bytes: lens mode and state.
template <class RosMsg, class Status>
RosMsg lens_and_state(const Status& status, const ros::Time& stamp) {
  RosMsg m;
  m.header = header(stamp);
  m.lens = code_of(status.lens);
  m.state = code_of(status.state);
  m.state_text = text_of(status.state);
  return m;
}

k40t_driver::PhotoStatus to_msg(const protocol::PhotoStatus& status, const ros::Time& stamp) {
  k40t_driver::PhotoStatus m = lens_and_state<k40t_driver::PhotoStatus>(status, stamp);
  m.burst_count = status.burst_count;
  return m;
}

k40t_driver::RecordStatus to_msg(const protocol::RecordStatus& status, const ros::Time& stamp) {
  k40t_driver::RecordStatus m = lens_and_state<k40t_driver::RecordStatus>(status, stamp);
  m.duration_s = status.recording_time_s;
  return m;
}

sensor_msgs::Range to_range(double distance_m, const ros::Time& stamp, const FrameIds& ids,
                            const RangeLimits& limits) {
  sensor_msgs::Range r;
  r.header = header(stamp, ids.laser);
  r.radiation_type = sensor_msgs::Range::INFRARED;  // a laser: the closest of the two types
  r.field_of_view = limits.field_of_view;
  r.min_range = limits.min_range;
  r.max_range = limits.max_range;
  r.range =
      distance_m > 0 ? static_cast<float>(distance_m) : std::numeric_limits<float>::infinity();
  return r;
}

sensor_msgs::NavSatFix to_nav_sat_fix(const protocol::TargetGpsAck& target, const ros::Time& stamp,
                                      const FrameIds& ids,
                                      const boost::array<double, 9>& covariance,
                                      protocol::LaserTargetZeros zeros) {
  sensor_msgs::NavSatFix fix;
  fix.header = header(stamp, ids.laser);
  fix.status.status = target.code == protocol::ResponseCode::kOk
                          ? sensor_msgs::NavSatStatus::STATUS_FIX
                          : sensor_msgs::NavSatStatus::STATUS_NO_FIX;
  fix.status.service = sensor_msgs::NavSatStatus::SERVICE_GPS;
  fix.latitude = target.latitude_deg;
  fix.longitude = target.longitude_deg;
  fix.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN;
  // No return is no place: no fix, and no height (not the geoid's 17 m at 0 deg, 0 deg).
  if (protocol::laser_target_no_return(target, zeros)) {
    fix.status.status = sensor_msgs::NavSatStatus::STATUS_NO_FIX;
    fix.altitude = std::numeric_limits<double>::quiet_NaN();
    return fix;
  }
  // The pod's altitude is above sea level; NavSatFix's is above the ellipsoid (NaN: unknown).
  const Result<double> ellipsoid = geo::Geoid::egm96().ellipsoid_from_msl(
      target.latitude_deg, target.longitude_deg, target.altitude_m);
  fix.altitude = ellipsoid ? ellipsoid.value() : std::numeric_limits<double>::quiet_NaN();
  if (covariance[0] < 0 || covariance[4] < 0 || covariance[8] < 0) return fix;
  fix.position_covariance = covariance;
  fix.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_APPROXIMATED;
  return fix;
}

k40t_driver::Frame to_frame_msg(const uint8_t* bytes, size_t size, const ros::Time& stamp,
                                uint8_t direction) {
  k40t_driver::Frame f;
  f.stamp = stamp;
  f.direction = direction;
  f.data.assign(bytes, bytes + size);
  return f;
}

void update_from_fix(VehicleState& state, const sensor_msgs::NavSatFix& fix,
                     double* reference_altitude_m) {
  GnssFix in;
  switch (fix.status.status) {
    case sensor_msgs::NavSatStatus::STATUS_FIX:
      in.quality = GnssFix::Quality::kFix;
      break;
    case sensor_msgs::NavSatStatus::STATUS_SBAS_FIX:
      in.quality = GnssFix::Quality::kSbas;
      break;
    case sensor_msgs::NavSatStatus::STATUS_GBAS_FIX:
      in.quality = GnssFix::Quality::kGbas;
      break;
    default:
      break;  // STATUS_NO_FIX
  }
  in.stamp_ns = static_cast<int64_t>(fix.header.stamp.toNSec());
  in.latitude_deg = fix.latitude;
  in.longitude_deg = fix.longitude;
  in.altitude_m = fix.altitude;
  if (fix.position_covariance_type != sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN) {
    in.covariance.emplace();
    std::copy(fix.position_covariance.begin(), fix.position_covariance.end(),
              in.covariance->begin());
  }
  apply_fix(state, in, reference_altitude_m);
}

void update_from_imu(VehicleState& state, const sensor_msgs::Imu& imu) {
  apply_enu_orientation(
      state, {imu.orientation.x, imu.orientation.y, imu.orientation.z, imu.orientation.w});
}

}  // namespace k40t::driver
