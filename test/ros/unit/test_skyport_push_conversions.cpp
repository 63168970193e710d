// The SKYPORT pushes as ROS messages (ros/skyport/push_conversions.h), on values worked by hand:
// dates to Unix time, NED cm/s to ENU m/s, the attitude's frames, fix states, covariances, and
// the heights (EGM96 check point of the NGA, as in test/unit/test_geodesy.cpp).
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "k40t_driver/ros/skyport/push_conversions.h"

namespace k40t::driver::skyport {
namespace {

using namespace psdk;

constexpr double kEps = 1e-9;
constexpr double kDegToRad = M_PI / 180.0;
const ros::Time kStamp(1000, 500);

// 2026-01-01 00:00:00 UTC: 56 years after 1970 with 14 leap days (1972..2024), 20454 days.
constexpr uint32_t kNewYear2026 = 20454u * 86400u;  // 1767225600

DateTime new_year_2026(uint8_t second) {
  return {2026, 1, 1, 0, 0, second};  // year, month, day, hour, minute, second
}

// Quaternions q and -q are the same rotation.
void expect_same_rotation(const geometry_msgs::Quaternion& q, double w, double x, double y,
                          double z) {
  const double sign = q.w * w + q.x * x + q.y * y + q.z * z < 0 ? -1.0 : 1.0;
  EXPECT_NEAR(sign * q.w, w, 1e-6);
  EXPECT_NEAR(sign * q.x, x, 1e-6);
  EXPECT_NEAR(sign * q.y, y, 1e-6);
  EXPECT_NEAR(sign * q.z, z, 1e-6);
}

TEST(SkyportPushConversions, DateTimeToUnixTime) {
  const ros::Time t = unix_time(new_year_2026(1), 250000);
  EXPECT_EQ(t.sec, kNewYear2026 + 1);
  EXPECT_EQ(t.nsec, 250000000u);
  const DateTime before_1970{1969, 12, 31, 23, 59, 59};
  EXPECT_EQ(unix_time(before_1970, 0).sec, 0u);  // -1 s is clamped, not wrapped to 2106
}

TEST(SkyportPushConversions, NedCentimetresPerSecondBecomeEnuMetresPerSecond) {
  const geometry_msgs::TwistStamped v = enu_velocity(kStamp, "enu", 100, 250, -50);
  EXPECT_EQ(v.header.stamp, kStamp);
  EXPECT_EQ(v.header.frame_id, "enu");
  EXPECT_NEAR(v.twist.linear.x, 2.5, kEps);  // east
  EXPECT_NEAR(v.twist.linear.y, 1.0, kEps);  // north
  EXPECT_NEAR(v.twist.linear.z, 0.5, kEps);  // up = -down
}

TEST(SkyportPushConversions, AttitudeAsPushedAndInRep103) {
  // Heading east (NED yaw 90 degrees), nose up 10 degrees: q = qz(90) * qy(10), worked out as
  // (c45 c5, -s45 s5, c45 s5, s45 c5).
  const double c45 = std::cos(45 * kDegToRad), s45 = std::sin(45 * kDegToRad);
  const double c5 = std::cos(5 * kDegToRad), s5 = std::sin(5 * kDegToRad);
  AttitudePush p;
  p.q0 = static_cast<float>(c45 * c5);
  p.q1 = static_cast<float>(-s45 * s5);
  p.q2 = static_cast<float>(c45 * s5);
  p.q3 = static_cast<float>(s45 * c5);
  const geometry_msgs::QuaternionStamped ned = ned_attitude(p, kStamp);
  EXPECT_EQ(ned.header.frame_id, "ned");
  EXPECT_EQ(ned.header.stamp, kStamp);
  EXPECT_FLOAT_EQ(ned.quaternion.w, p.q0);
  EXPECT_FLOAT_EQ(ned.quaternion.x, p.q1);
  EXPECT_FLOAT_EQ(ned.quaternion.y, p.q2);
  EXPECT_FLOAT_EQ(ned.quaternion.z, p.q3);

  // In ENU, east is yaw 0, and nose up is a negative pitch about FLU's y (left): qy(-10).
  const sensor_msgs::Imu imu = enu_attitude(p, kStamp, "base_link");
  EXPECT_EQ(imu.header.frame_id, "base_link");
  expect_same_rotation(imu.orientation, c5, 0, -s5, 0);
  EXPECT_EQ(imu.angular_velocity_covariance[0], -1);
  EXPECT_EQ(imu.linear_acceleration_covariance[0], -1);

  // Level, heading north (identity in NED): ENU yaw +90 degrees, (c45, 0, 0, s45).
  const sensor_msgs::Imu north = enu_attitude(AttitudePush{}, kStamp, "base_link");
  expect_same_rotation(north.orientation, c45, 0, 0, s45);
}

TEST(SkyportPushConversions, FusedGpsInDegreesWithoutAltitude) {
  GpsPush p;
  p.latitude_rad = M_PI / 6;    // 30 degrees
  p.longitude_rad = -M_PI / 4;  // -45 degrees
  p.signal = GpsSignal::kMedium;
  const sensor_msgs::NavSatFix fix = gps_fix(p, kStamp, "enu");
  EXPECT_NEAR(fix.latitude, 30.0, kEps);
  EXPECT_NEAR(fix.longitude, -45.0, kEps);
  EXPECT_TRUE(std::isnan(fix.altitude));  // only the height above take-off is pushed
  EXPECT_EQ(fix.status.status, sensor_msgs::NavSatStatus::STATUS_FIX);
  EXPECT_EQ(fix.status.service, sensor_msgs::NavSatStatus::SERVICE_GPS);
  EXPECT_EQ(fix.position_covariance_type, sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN);
  p.signal = GpsSignal::kNone;
  EXPECT_EQ(gps_fix(p, kStamp, "enu").status.status, sensor_msgs::NavSatStatus::STATUS_NO_FIX);
}

TEST(SkyportPushConversions, RawGpsHeightAboveTheEllipsoidAndDiagonalCovariance) {
  RawGpsPush p;
  p.latitude_deg = 46.8743190;  // NGA check point: the geoid 43.575 m below the ellipsoid
  p.longitude_deg = 102.4487290;
  p.height_m = 1000;
  p.fix_state = 3;
  p.horizontal_accuracy_mm = 2000;  // 2 m -> 4 m^2
  p.vertical_accuracy_mm = 3000;    // 3 m -> 9 m^2
  p.velocity_north_cm_s = -300;
  p.velocity_east_cm_s = 0;
  p.velocity_down_cm_s = 100;
  const sensor_msgs::NavSatFix fix = raw_gps_fix(p, kStamp, "enu");
  EXPECT_NEAR(fix.altitude, 1000 - 43.575, 0.1);
  EXPECT_EQ(fix.status.status, sensor_msgs::NavSatStatus::STATUS_FIX);
  const std::array<double, 9> covariance{4, 0, 0, 0, 4, 0, 0, 0, 9};
  for (size_t i = 0; i < 9; ++i) EXPECT_NEAR(fix.position_covariance[i], covariance[i], kEps) << i;
  EXPECT_EQ(fix.position_covariance_type, sensor_msgs::NavSatFix::COVARIANCE_TYPE_DIAGONAL_KNOWN);
  p.fix_state = 2;  // 2D: not a fix for the pod
  EXPECT_EQ(raw_gps_fix(p, kStamp, "enu").status.status, sensor_msgs::NavSatStatus::STATUS_NO_FIX);
  const geometry_msgs::TwistStamped v = raw_gps_velocity(p, kStamp, "enu");
  EXPECT_NEAR(v.twist.linear.x, 0.0, kEps);
  EXPECT_NEAR(v.twist.linear.y, -3.0, kEps);
  EXPECT_NEAR(v.twist.linear.z, -1.0, kEps);
}

TEST(SkyportPushConversions, RtkPositionTypeGivesTheFixStatus) {
  RawRtkPush p;
  p.latitude_deg = 46.8743190;
  p.longitude_deg = 102.4487290;
  p.height_m = 1000;
  p.velocity_east_cm_s = 150;
  p.position_type = 0;
  EXPECT_EQ(rtk_fix(p, kStamp, "enu").status.status, sensor_msgs::NavSatStatus::STATUS_NO_FIX);
  p.position_type = 16;  // single point
  EXPECT_EQ(rtk_fix(p, kStamp, "enu").status.status, sensor_msgs::NavSatStatus::STATUS_FIX);
  p.position_type = 50;  // narrow integer: RTK fixed
  const sensor_msgs::NavSatFix fixed = rtk_fix(p, kStamp, "enu");
  EXPECT_EQ(fixed.status.status, sensor_msgs::NavSatStatus::STATUS_GBAS_FIX);
  EXPECT_NEAR(fixed.altitude, 1000 - 43.575, 0.1);
  EXPECT_NEAR(rtk_velocity(p, kStamp, "enu").twist.linear.x, 1.5, kEps);
}

TEST(SkyportPushConversions, UavStateBarometerAndLinkFieldByField) {
  UavStatePush p;
  p.state.compass_abnormal = true;
  p.state.landing = LandingState::kInTheSky;
  p.flight_time_s = 12.3;
  p.drone_type = DroneType::kM210Rtk;
  const k40t_driver::UavState s = uav_state(p, kStamp);
  EXPECT_TRUE(s.compass_abnormal);
  EXPECT_FALSE(s.motors_rotating);
  EXPECT_EQ(s.landing, k40t_driver::UavState::LANDING_IN_THE_SKY);
  EXPECT_FLOAT_EQ(s.flight_time_s, 12.3f);
  EXPECT_EQ(s.drone_type, 3);
  EXPECT_EQ(s.drone_type_text, "M210 RTK");
  p.drone_type = static_cast<DroneType>(42);  // not in 3.3.5's table
  EXPECT_EQ(uav_state(p, kStamp).drone_type_text, "unknown");

  BarometricAltitudePush baro;
  baro.altitude_m = 123.5f;
  EXPECT_FLOAT_EQ(barometric_altitude(baro, kStamp).altitude_m, 123.5f);

  LinkBandwidthPush link;
  link.image_link_normal = true;
  link.connection.app_connected = true;
  link.msdk_uplink_bytes_s = 1111;
  link.network_data_kbit_s = 2222;
  link.osdk_uplink_bytes_s = 3333;
  const k40t_driver::LinkBandwidth l = link_bandwidth(link, kStamp);
  EXPECT_EQ(l.header.stamp, kStamp);
  EXPECT_TRUE(l.image_link_normal);
  EXPECT_TRUE(l.app_connected);
  EXPECT_FALSE(l.remote_controller_connected);
  EXPECT_EQ(l.msdk_uplink_bytes_s, 1111u);
  EXPECT_EQ(l.network_data_kbit_s, 2222u);
  EXPECT_EQ(l.osdk_uplink_bytes_s, 3333u);
}

TEST(SkyportPushConversions, TimesAppAndUtc) {
  AppDateTimePush app;
  app.time = new_year_2026(0);
  const sensor_msgs::TimeReference a = app_time(app, kStamp);
  EXPECT_EQ(a.header.stamp, kStamp);
  EXPECT_EQ(a.time_ref, ros::Time(kNewYear2026, 0));
  EXPECT_EQ(a.source, "dji_app");

  UtcTimePush utc;
  utc.time = new_year_2026(30);
  utc.microsecond = 500000;
  const ros::Time edge(5000, 0);
  const sensor_msgs::TimeReference u = utc_time(utc, edge);
  EXPECT_EQ(u.header.stamp, edge);  // the edge on this computer's clock
  EXPECT_EQ(u.time_ref, ros::Time(kNewYear2026 + 30, 500000000));
  EXPECT_EQ(u.source, "skyport_pps");
}

TEST(SkyportPushConversions, OtherPayloadAndBattery) {
  const k40t_driver::OtherPayload z30 = other_payload(2, 43.5f, kStamp);
  EXPECT_EQ(z30.type, k40t_driver::OtherPayload::TYPE_ZENMUSE_Z30);
  EXPECT_EQ(z30.type_text, "ZENMUSE Z30");
  EXPECT_FLOAT_EQ(z30.focal_length_mm, 43.5f);
  const k40t_driver::OtherPayload unknown = other_payload(9, std::nanf(""), kStamp);
  EXPECT_EQ(unknown.type_text, "unknown");
  EXPECT_TRUE(std::isnan(unknown.focal_length_mm));

  BatteryInfoPush battery;
  battery.percentage = 87;
  const sensor_msgs::BatteryState b = battery_state(battery, kStamp);
  EXPECT_FLOAT_EQ(b.percentage, 0.87f);
  EXPECT_TRUE(std::isnan(b.voltage));
  EXPECT_TRUE(std::isnan(b.design_capacity));
  EXPECT_TRUE(b.present);
  EXPECT_EQ(b.power_supply_status, sensor_msgs::BatteryState::POWER_SUPPLY_STATUS_DISCHARGING);
}

TEST(SkyportPushConversions, PositionPointsStampedAndNoFixWithoutSolution) {
  const int64_t time_ns = int64_t{kNewYear2026 + 1} * 1000000000 + 250000000;
  const sensor_msgs::NavSatFix missing = position_fix(std::nullopt, time_ns, "enu");
  EXPECT_EQ(missing.header.stamp, ros::Time(kNewYear2026 + 1, 250000000));
  EXPECT_EQ(missing.header.frame_id, "enu");
  EXPECT_EQ(missing.status.status, sensor_msgs::NavSatStatus::STATUS_NO_FIX);
  EXPECT_TRUE(std::isnan(missing.latitude));

  TargetPosition point;
  point.latitude_deg = 22.5;
  point.longitude_deg = 113.9;
  point.height_m = 120.0;
  point.solution = PositionSolution::kNotAvailable;
  const sensor_msgs::NavSatFix none = position_fix(point, time_ns, "enu");
  EXPECT_EQ(none.status.status, sensor_msgs::NavSatStatus::STATUS_NO_FIX);
  EXPECT_TRUE(std::isnan(none.altitude));

  point.solution = PositionSolution::kFixed;
  const sensor_msgs::NavSatFix fixed = position_fix(point, time_ns, "enu");
  EXPECT_EQ(fixed.status.status, sensor_msgs::NavSatStatus::STATUS_FIX);
  EXPECT_NEAR(fixed.latitude, 22.5, kEps);
  EXPECT_NEAR(fixed.longitude, 113.9, kEps);
  EXPECT_NEAR(fixed.altitude, 120.0, kEps);  // above sea level, as GetPosition.srv says
}

}  // namespace
}  // namespace k40t::driver::skyport
