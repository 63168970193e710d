#include "k40t_driver/ros/skyport/push_conversions.h"

#include <algorithm>
#include <cmath>

#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>

#include "k40t_driver/geo/geodesy.h"
#include "k40t_driver/skyport/position_request.h"

namespace k40t::driver::skyport {

using namespace psdk;

namespace {
constexpr double kDegPerRad = 180.0 / M_PI;
}  // namespace

ros::Time unix_time(const DateTime& t, uint32_t microsecond) {
  return ros::Time(static_cast<uint32_t>(std::max<int64_t>(unix_seconds(t), 0)),
                   microsecond * 1000);
}

geometry_msgs::TwistStamped enu_velocity(const ros::Time& stamp, const std::string& frame,
                                         double north_cm_s, double east_cm_s, double down_cm_s) {
  geometry_msgs::TwistStamped out;
  out.header.stamp = stamp;
  out.header.frame_id = frame;
  out.twist.linear.x = east_cm_s / 100.0;
  out.twist.linear.y = north_cm_s / 100.0;
  out.twist.linear.z = -down_cm_s / 100.0;
  return out;
}

sensor_msgs::NavSatFix fix_message(const ros::Time& stamp, const std::string& frame,
                                   double latitude_deg, double longitude_deg, double altitude_msl_m,
                                   int8_t status) {
  sensor_msgs::NavSatFix fix;
  fix.header.stamp = stamp;
  fix.header.frame_id = frame;
  fix.latitude = latitude_deg;
  fix.longitude = longitude_deg;
  const Result<double> ellipsoid =
      geo::Geoid::egm96().ellipsoid_from_msl(latitude_deg, longitude_deg, altitude_msl_m);
  fix.altitude = ellipsoid ? ellipsoid.value() : std::nan("");
  fix.status.status = status;
  fix.status.service = sensor_msgs::NavSatStatus::SERVICE_GPS;
  fix.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN;
  return fix;
}

geometry_msgs::QuaternionStamped ned_attitude(const AttitudePush& p, const ros::Time& stamp) {
  geometry_msgs::QuaternionStamped q;
  q.header.stamp = stamp;
  q.header.frame_id = "ned";
  q.quaternion.w = p.q0;
  q.quaternion.x = p.q1;
  q.quaternion.y = p.q2;
  q.quaternion.z = p.q3;
  return q;
}

sensor_msgs::Imu enu_attitude(const AttitudePush& p, const ros::Time& stamp,
                              const std::string& base_frame) {
  double roll = 0, pitch = 0, yaw = 0;
  tf2::Matrix3x3(tf2::Quaternion(p.q1, p.q2, p.q3, p.q0).normalized()).getRPY(roll, pitch, yaw);
  tf2::Quaternion enu;
  enu.setRPY(roll, -pitch, M_PI / 2 - yaw);
  sensor_msgs::Imu imu;
  imu.header.stamp = stamp;
  imu.header.frame_id = base_frame;
  imu.orientation.x = enu.x();
  imu.orientation.y = enu.y();
  imu.orientation.z = enu.z();
  imu.orientation.w = enu.w();
  imu.angular_velocity_covariance[0] = -1;  // not pushed
  imu.linear_acceleration_covariance[0] = -1;
  return imu;
}

sensor_msgs::NavSatFix gps_fix(const GpsPush& p, const ros::Time& stamp, const std::string& frame) {
  return fix_message(stamp, frame, p.latitude_rad * kDegPerRad, p.longitude_rad * kDegPerRad,
                     std::nan(""),
                     p.signal == GpsSignal::kNone ? sensor_msgs::NavSatStatus::STATUS_NO_FIX
                                                  : sensor_msgs::NavSatStatus::STATUS_FIX);
}

sensor_msgs::NavSatFix raw_gps_fix(const RawGpsPush& p, const ros::Time& stamp,
                                   const std::string& frame) {
  sensor_msgs::NavSatFix fix =
      fix_message(stamp, frame, p.latitude_deg, p.longitude_deg, p.height_m,
                  p.fix_state >= 3 ? sensor_msgs::NavSatStatus::STATUS_FIX
                                   : sensor_msgs::NavSatStatus::STATUS_NO_FIX);
  const double h = p.horizontal_accuracy_mm / 1000.0, v = p.vertical_accuracy_mm / 1000.0;
  fix.position_covariance = {h * h, 0, 0, 0, h * h, 0, 0, 0, v * v};
  fix.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_DIAGONAL_KNOWN;
  return fix;
}

sensor_msgs::NavSatFix rtk_fix(const RawRtkPush& p, const ros::Time& stamp,
                               const std::string& frame) {
  const int8_t status = p.position_type == 0    ? sensor_msgs::NavSatStatus::STATUS_NO_FIX
                        : p.position_type >= 50 ? sensor_msgs::NavSatStatus::STATUS_GBAS_FIX
                                                : sensor_msgs::NavSatStatus::STATUS_FIX;
  return fix_message(stamp, frame, p.latitude_deg, p.longitude_deg, p.height_m, status);
}

k40t_driver::UavState uav_state(const UavStatePush& p, const ros::Time& stamp) {
  k40t_driver::UavState out;
  out.header.stamp = stamp;
  out.compass_abnormal = p.state.compass_abnormal;
  out.motors_rotating = p.state.motors_rotating;
  out.landing = static_cast<uint8_t>(p.state.landing);
  out.flight_time_s = static_cast<float>(p.flight_time_s);
  out.drone_type = static_cast<uint8_t>(p.drone_type);
  const char* text = to_string(p.drone_type);
  out.drone_type_text = text ? text : "unknown";
  return out;
}

k40t_driver::LinkBandwidth link_bandwidth(const LinkBandwidthPush& p, const ros::Time& stamp) {
  k40t_driver::LinkBandwidth out;
  out.header.stamp = stamp;
  out.image_link_normal = p.image_link_normal;
  out.max_image_link_bandwidth = p.max_image_link_bandwidth;
  out.remote_controller_connected = p.connection.remote_controller_connected;
  out.image_downlink_connected = p.connection.image_downlink_connected;
  out.data_downlink_connected = p.connection.data_downlink_connected;
  out.app_connected = p.connection.app_connected;
  out.msdk_uplink_max_bytes_s = p.msdk_uplink_max_bytes_s;
  out.msdk_downlink_max_bytes_s = p.msdk_downlink_max_bytes_s;
  out.msdk_uplink_bytes_s = p.msdk_uplink_bytes_s;
  out.msdk_downlink_bytes_s = p.msdk_downlink_bytes_s;
  out.network_max_kbit_s = p.network_max_kbit_s;
  out.network_video_kbit_s = p.network_video_kbit_s;
  out.network_data_kbit_s = p.network_data_kbit_s;
  out.osdk_uplink_max_bytes_s = p.osdk_uplink_max_bytes_s;
  out.osdk_uplink_bytes_s = p.osdk_uplink_bytes_s;
  return out;
}

k40t_driver::BarometricAltitude barometric_altitude(const BarometricAltitudePush& p,
                                                    const ros::Time& stamp) {
  k40t_driver::BarometricAltitude out;
  out.header.stamp = stamp;
  out.altitude_m = p.altitude_m;
  return out;
}

sensor_msgs::TimeReference app_time(const AppDateTimePush& p, const ros::Time& stamp) {
  sensor_msgs::TimeReference out;
  out.header.stamp = stamp;
  out.time_ref = unix_time(p.time, 0);
  out.source = "dji_app";
  return out;
}

sensor_msgs::TimeReference utc_time(const UtcTimePush& p, const ros::Time& edge_stamp) {
  sensor_msgs::TimeReference out;
  out.header.stamp = edge_stamp;
  out.time_ref = unix_time(p.time, p.microsecond);
  out.source = "skyport_pps";
  return out;
}

k40t_driver::OtherPayload other_payload(uint8_t type, float focal_length_mm,
                                        const ros::Time& stamp) {
  k40t_driver::OtherPayload out;
  out.header.stamp = stamp;
  out.type = type;
  const char* text = to_string(static_cast<OtherPayloadType>(type));
  out.type_text = text ? text : "unknown";
  out.focal_length_mm = focal_length_mm;
  return out;
}

sensor_msgs::BatteryState battery_state(const BatteryInfoPush& p, const ros::Time& stamp) {
  sensor_msgs::BatteryState battery;
  battery.header.stamp = stamp;
  battery.percentage = p.percentage / 100.0f;
  battery.voltage = battery.current = battery.charge = battery.capacity = std::nanf("");
  battery.design_capacity = std::nanf("");
  battery.present = true;
  battery.power_supply_status = sensor_msgs::BatteryState::POWER_SUPPLY_STATUS_DISCHARGING;
  return battery;
}

sensor_msgs::NavSatFix position_fix(const std::optional<TargetPosition>& point, int64_t time_ns,
                                    const std::string& frame) {
  sensor_msgs::NavSatFix fix;
  fix.header.frame_id = frame;
  fix.header.stamp.fromNSec(static_cast<uint64_t>(time_ns));
  fix.status.service = sensor_msgs::NavSatStatus::SERVICE_GPS;
  fix.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN;
  const bool fix_ok = point && is_fix(point->solution);
  fix.status.status =
      fix_ok ? sensor_msgs::NavSatStatus::STATUS_FIX : sensor_msgs::NavSatStatus::STATUS_NO_FIX;
  fix.latitude = fix_ok ? point->latitude_deg : std::nan("");
  fix.longitude = fix_ok ? point->longitude_deg : std::nan("");
  // As answered, above sea level (GetPosition.srv says so), unlike the pushes' fixes.
  fix.altitude = fix_ok ? point->height_m : std::nan("");
  return fix;
}

}  // namespace k40t::driver::skyport
