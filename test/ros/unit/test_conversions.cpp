// Conversions to and from ROS messages: units, frame ids, TF, the laser target, and what the
// vehicle messages hand to driver/vehicle_inputs.h (whose rules test/unit/test_vehicle_inputs.cpp
// checks).
#include <gtest/gtest.h>

#include <cmath>

#include <tf2/LinearMath/Quaternion.h>
#include <tf2/LinearMath/Vector3.h>

#include "../../unit/message_text.h"  // test/unit/message_text.h
#include "k40t_driver/ros/conversions.h"
#include "k40t_driver/ros/geo_glue.h"

namespace k40t::driver {
namespace {

constexpr double kEps = 1e-9;

tf2::Quaternion as_tf(const geometry_msgs::Quaternion& q) {
  return tf2::Quaternion(q.x, q.y, q.z, q.w);
}

TEST(JointState, NamesPositionsVelocitiesAndStamp) {
  protocol::GimbalAttitude att;
  att.joint_yaw_deg = -45.0;  // left 45
  att.joint_roll_deg = 2.0;
  att.joint_pitch_deg = -90.0;  // straight down
  att.yaw_rate_deg_s = 10.0;
  att.roll_rate_deg_s = 0.0;
  att.pitch_rate_deg_s = -5.0;
  const ros::Time stamp(1234, 5678);
  const sensor_msgs::JointState js = to_joint_state(att, stamp, FrameIds("p_", "j_"));
  EXPECT_EQ(js.header.stamp, stamp);
  ASSERT_EQ(js.name.size(), 3u);
  EXPECT_EQ(js.name[0], "j_yaw_joint");
  EXPECT_EQ(js.name[1], "j_roll_joint");
  EXPECT_EQ(js.name[2], "j_pitch_joint");
  EXPECT_NEAR(js.position[0], M_PI / 4, kEps);
  EXPECT_NEAR(js.position[1], 2.0 * M_PI / 180, kEps);
  EXPECT_NEAR(js.position[2], M_PI / 2, kEps);
  EXPECT_NEAR(js.velocity[0], -10.0 * M_PI / 180, kEps);
  EXPECT_NEAR(js.velocity[2], 5.0 * M_PI / 180, kEps);
}

TEST(Transforms, PitchDownTurnsTheCameraAxisDown) {
  protocol::GimbalAttitude att;
  att.joint_pitch_deg = -90.0;  // pod: 90 down
  const FrameIds ids;
  const auto chain = gimbal_transforms(att, ros::Time(1), ids, GimbalGeometry{});
  ASSERT_EQ(chain.size(), 3u);
  EXPECT_EQ(chain[0].header.frame_id, "k40t_base_link");
  EXPECT_EQ(chain[0].child_frame_id, "k40t_yaw_link");
  EXPECT_EQ(chain[2].header.frame_id, "k40t_roll_link");
  EXPECT_EQ(chain[2].child_frame_id, "k40t_pitch_link");
  const tf2::Vector3 forward =
      tf2::quatRotate(as_tf(chain[2].transform.rotation), tf2::Vector3(1, 0, 0));
  EXPECT_NEAR(forward.z(), -1.0, 1e-6);  // the x axis of the pitch link points down
}

TEST(Transforms, OpticalFramesLookAlongThePitchLinkX) {
  const FrameIds ids("pod_");
  const auto sensors = sensor_transforms(ros::Time(1), ids, GimbalGeometry{});
  ASSERT_EQ(sensors.size(), 4u);
  for (size_t i = 0; i < 3; ++i) {  // tele, wide, thermal: optical z = link x, optical x = link -y
    EXPECT_EQ(sensors[i].header.frame_id, "pod_pitch_link");
    const tf2::Quaternion q = as_tf(sensors[i].transform.rotation);
    const tf2::Vector3 z = tf2::quatRotate(q, tf2::Vector3(0, 0, 1));
    const tf2::Vector3 x = tf2::quatRotate(q, tf2::Vector3(1, 0, 0));
    EXPECT_NEAR(z.x(), 1.0, 1e-6) << sensors[i].child_frame_id;
    EXPECT_NEAR(x.y(), -1.0, 1e-6) << sensors[i].child_frame_id;
  }
  EXPECT_EQ(sensors[0].child_frame_id, "pod_tele_optical_frame");
  EXPECT_EQ(sensors[3].child_frame_id, "pod_laser_frame");
  EXPECT_NEAR(sensors[3].transform.rotation.w, 1.0, 1e-9);  // the laser frame is not rotated
}

TEST(Range, NoReturnIsPlusInfinityInTheLaserFrame) {
  const RangeLimits limits;
  const sensor_msgs::Range none = to_range(0.0, ros::Time(2), FrameIds(), limits);
  EXPECT_TRUE(std::isinf(none.range) && none.range > 0);
  EXPECT_EQ(none.header.frame_id, "k40t_laser_frame");
  const sensor_msgs::Range hit = to_range(123.4, ros::Time(2), FrameIds(), limits);
  EXPECT_FLOAT_EQ(hit.range, 123.4f);
  EXPECT_FLOAT_EQ(hit.min_range, limits.min_range);
  EXPECT_FLOAT_EQ(hit.max_range, limits.max_range);
}

// laser/target carries laser/target_report's covariance: approximated with a vehicle fix,
// unknown (zeros) without one, as the report's all -1 says.
TEST(LaserTarget, NavSatFixCarriesTheReportsCovariance) {
  protocol::TargetGpsAck ack;
  ack.latitude_deg = 22.5;
  ack.longitude_deg = 113.9;
  ack.altitude_m = 10.0;
  VehicleState vehicle;
  vehicle.has_fix = true;
  vehicle.latitude_deg = 22.5;
  vehicle.longitude_deg = 113.9;
  vehicle.altitude_m = 400.0;  // far above the target: a slant of a few hundred metres
  const k40t_driver::LaserTarget report =
      to_laser_target(ack, ros::Time(3), "laser", vehicle, protocol::LaserTargetZeros::kNoReturn);
  ASSERT_GT(report.position_covariance[0], vehicle.position_covariance[0]);
  const sensor_msgs::NavSatFix fix =
      to_nav_sat_fix(ack, ros::Time(3), FrameIds(), report.position_covariance,
                     protocol::LaserTargetZeros::kNoReturn);
  EXPECT_EQ(fix.position_covariance_type, sensor_msgs::NavSatFix::COVARIANCE_TYPE_APPROXIMATED);
  for (size_t i = 0; i < 9; ++i)
    EXPECT_EQ(fix.position_covariance[i], report.position_covariance[i]);
  EXPECT_EQ(fix.status.status, sensor_msgs::NavSatStatus::STATUS_FIX);

  const k40t_driver::LaserTarget blind = to_laser_target(ack, ros::Time(3), "laser", VehicleState(),
                                                         protocol::LaserTargetZeros::kNoReturn);
  ASSERT_EQ(blind.position_covariance[0], -1.0);
  const sensor_msgs::NavSatFix unknown =
      to_nav_sat_fix(ack, ros::Time(3), FrameIds(), blind.position_covariance,
                     protocol::LaserTargetZeros::kNoReturn);
  EXPECT_EQ(unknown.position_covariance_type, sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN);
  for (double c : unknown.position_covariance) EXPECT_EQ(c, 0.0);
}

// An OK answer at 0 deg, 0 deg is "no return" under laser_target_zeros: no_return (the default):
// no position, so no ellipsoid altitude (not the geoid's 17 m at 0 deg, 0 deg) and no covariance
// (not one from a vehicle thousands of km away), however good the vehicle's fix; laser/target
// says no fix with an unknown covariance. Under "position" the same zeros are a place.
TEST(LaserTarget, NoReturnZerosAreNoPosition) {
  const protocol::TargetGpsAck zeros;  // code OK, every field 0
  VehicleState vehicle;
  vehicle.has_fix = true;
  vehicle.latitude_deg = 47.3977;
  vehicle.longitude_deg = 8.5456;
  vehicle.altitude_m = 500.0;
  const k40t_driver::LaserTarget report =
      to_laser_target(zeros, ros::Time(3), "laser", vehicle, protocol::LaserTargetZeros::kNoReturn);
  EXPECT_EQ(report.code, 0);
  EXPECT_EQ(report.latitude, 0.0);
  EXPECT_EQ(report.longitude, 0.0);
  EXPECT_EQ(report.altitude_msl, 0.0);
  EXPECT_TRUE(std::isnan(report.altitude));
  for (double c : report.position_covariance) EXPECT_EQ(c, -1.0);
  const sensor_msgs::NavSatFix fix =
      to_nav_sat_fix(zeros, ros::Time(3), FrameIds(), report.position_covariance,
                     protocol::LaserTargetZeros::kNoReturn);
  EXPECT_EQ(fix.position_covariance_type, sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN);
  EXPECT_EQ(fix.status.status, sensor_msgs::NavSatStatus::STATUS_NO_FIX);
  EXPECT_TRUE(std::isnan(fix.altitude)) << fix.altitude;  // not the geoid's 17.16 m there

  const k40t_driver::LaserTarget place =
      to_laser_target(zeros, ros::Time(3), "laser", vehicle, protocol::LaserTargetZeros::kPosition);
  EXPECT_NEAR(place.altitude, 17.16, 0.1);  // EGM96's undulation at 0 deg, 0 deg
  EXPECT_GT(place.position_covariance[0], 0.0);
  const sensor_msgs::NavSatFix place_fix =
      to_nav_sat_fix(zeros, ros::Time(3), FrameIds(), place.position_covariance,
                     protocol::LaserTargetZeros::kPosition);
  EXPECT_EQ(place_fix.status.status, sensor_msgs::NavSatStatus::STATUS_FIX);
  EXPECT_NEAR(place_fix.altitude, 17.16, 0.1);
}

TEST(ThermalStats, DegreesCoordinatesAndAlarms) {
  const auto t = k40t::testing::message_from_text<protocol::ThermalStatus>(
      "max_degC=85.3 min_degC=-12.5 center_degC=20.1 max_x_px=700 max_y_px=500 point_x_px=960 "
      "high_alarm=true");
  const k40t_driver::ThermalStats m = to_msg(t, ros::Time(3), FrameIds());
  EXPECT_FLOAT_EQ(m.max_degC, 85.3f);
  EXPECT_FLOAT_EQ(m.min_degC, -12.5f);
  EXPECT_FLOAT_EQ(m.centre_degC, 20.1f);
  EXPECT_EQ(m.max_x, 700);
  EXPECT_EQ(m.max_y, 500);
  EXPECT_EQ(m.point_x, 960);
  EXPECT_TRUE(m.high_alarm);
  EXPECT_FALSE(m.low_alarm);
  EXPECT_EQ(m.header.frame_id, "k40t_thermal_optical_frame");
}

TEST(VehicleState, NavSatFixStatusAndCovarianceTypeAreCopied) {
  sensor_msgs::NavSatFix fix;
  fix.latitude = 47.1;
  fix.longitude = 8.5;
  fix.altitude = 500.0;
  fix.position_covariance = {1, 0, 0, 0, 1, 0, 0, 0, 9};
  fix.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN;
  // 0x000320 byte 2: GBAS (DGPS, float or fixed RTK alike) is 4, never 6 "fixed RTK".
  const std::pair<int8_t, uint8_t> statuses[] = {{sensor_msgs::NavSatStatus::STATUS_FIX, 3},
                                                 {sensor_msgs::NavSatStatus::STATUS_SBAS_FIX, 4},
                                                 {sensor_msgs::NavSatStatus::STATUS_GBAS_FIX, 4},
                                                 {sensor_msgs::NavSatStatus::STATUS_NO_FIX, 1}};
  for (const auto& [status, pod_status] : statuses) {
    VehicleState s;
    fix.status.status = status;
    update_from_fix(s, fix, nullptr);
    EXPECT_EQ(s.gps_status, pod_status) << int(status);
    EXPECT_EQ(s.has_fix, status != sensor_msgs::NavSatStatus::STATUS_NO_FIX) << int(status);
    EXPECT_EQ(s.position_covariance, VehicleState().position_covariance);  // type unknown
  }
  VehicleState s;
  fix.status.status = sensor_msgs::NavSatStatus::STATUS_FIX;
  fix.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_DIAGONAL_KNOWN;
  update_from_fix(s, fix, nullptr);
  EXPECT_EQ(s.position_covariance[8], 9.0);
  sensor_msgs::Imu imu;
  imu.orientation.w = 1.0;  // level, facing east
  update_from_imu(s, imu);
  EXPECT_TRUE(s.has_attitude);
  EXPECT_NEAR(s.heading_deg, 90.0, 1e-9);
}

}  // namespace
}  // namespace k40t::driver
