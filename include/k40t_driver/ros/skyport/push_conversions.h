// The SKYPORT adapter's data pushes (PSDK 0x03, docs/skyport.md) and positioning answers as ROS
// messages. Pure functions like ros/conversions.h: no node handles, no clocks (the stamp is an
// argument), so each can be checked on hand-worked values (test/ros/unit/
// test_skyport_push_conversions.cpp).
//
// Frames and units. The adapter pushes NED velocities in cm/s and an FRD body -> NED attitude;
// ROS wants REP 103 (ENU, FLU, m/s). Heights are pushed above mean sea level (3.3.8, 3.3.9);
// NavSatFix wants them above the WGS 84 ellipsoid (docs/geo.md), so the EGM96 undulation is added.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include <geometry_msgs/QuaternionStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <ros/time.h>
#include <sensor_msgs/BatteryState.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/NavSatFix.h>
#include <sensor_msgs/TimeReference.h>

#include "k40t_driver/BarometricAltitude.h"
#include "k40t_driver/LinkBandwidth.h"
#include "k40t_driver/OtherPayload.h"
#include "k40t_driver/UavState.h"
#include "k40t_driver/psdk/commands/data_push.h"
#include "k40t_driver/psdk/commands/positioning.h"

namespace k40t::driver::skyport {

// The UTC instant of a PSDK date-time plus `microsecond` (a date before 1970 gives 0 s).
ros::Time unix_time(const psdk::DateTime& t, uint32_t microsecond);

// NED velocity in cm/s -> ENU m/s.
geometry_msgs::TwistStamped enu_velocity(const ros::Time& stamp, const std::string& frame,
                                         double north_cm_s, double east_cm_s, double down_cm_s);

// A fix at a height above mean sea level (NaN: unknown; a height the geoid cannot convert stays
// unknown too), unknown covariance, GPS service.
sensor_msgs::NavSatFix fix_message(const ros::Time& stamp, const std::string& frame,
                                   double latitude_deg, double longitude_deg, double altitude_msl_m,
                                   int8_t status);

// 3.3.2 as pushed: body (FRD) -> NED, frame "ned".
geometry_msgs::QuaternionStamped ned_attitude(const psdk::AttitudePush& p, const ros::Time& stamp);
// 3.3.2 in REP 103: `base_frame` (FLU) in ENU (same roll, pitch negated, yaw from east
// counter-clockwise); no rates or accelerations (their covariances -1).
sensor_msgs::Imu enu_attitude(const psdk::AttitudePush& p, const ros::Time& stamp,
                              const std::string& base_frame);

// 3.3.4: the fused position, which carries only the height above take-off: altitude NaN. No fix
// when the signal is "none".
sensor_msgs::NavSatFix gps_fix(const psdk::GpsPush& p, const ros::Time& stamp,
                               const std::string& frame);
// 3.3.8: fixed from fix state 3 (3D) on; the accuracies (mm) as a diagonal covariance.
sensor_msgs::NavSatFix raw_gps_fix(const psdk::RawGpsPush& p, const ros::Time& stamp,
                                   const std::string& frame);
// 3.3.9: position type 0 no solution, 50 (narrow integer, DJI's numbering) and above RTK fixed
// (GBAS), anything else a fix.
sensor_msgs::NavSatFix rtk_fix(const psdk::RawRtkPush& p, const ros::Time& stamp,
                               const std::string& frame);
// 3.3.8, 3.3.9: a receiver's NED velocity (cm/s), which both pushes carry in the same fields.
template <class ReceiverPush>
geometry_msgs::TwistStamped receiver_velocity(const ReceiverPush& p, const ros::Time& stamp,
                                              const std::string& frame) {
  return enu_velocity(stamp, frame, p.velocity_north_cm_s, p.velocity_east_cm_s,
                      p.velocity_down_cm_s);
}
inline constexpr auto raw_gps_velocity = &receiver_velocity<psdk::RawGpsPush>;
inline constexpr auto rtk_velocity = &receiver_velocity<psdk::RawRtkPush>;

k40t_driver::UavState uav_state(const psdk::UavStatePush& p, const ros::Time& stamp);
// 3.3.1 in either length; `osdk_uplink_bytes_s` is 0 when the push had no OSDK fields.
k40t_driver::LinkBandwidth link_bandwidth(const psdk::LinkBandwidthPush& p, const ros::Time& stamp);
k40t_driver::BarometricAltitude barometric_altitude(const psdk::BarometricAltitudePush& p,
                                                    const ros::Time& stamp);
// 3.3.6: the app's date-time, source "dji_app".
sensor_msgs::TimeReference app_time(const psdk::AppDateTimePush& p, const ros::Time& stamp);
// 3.3.10: the UTC instant of the PPS edge; `edge_stamp` is that edge on this computer's clock.
sensor_msgs::TimeReference utc_time(const psdk::UtcTimePush& p, const ros::Time& edge_stamp);
// 3.3.11 + 3.3.12, latched together: `focal_length_mm` NaN until a focal-length push arrived.
k40t_driver::OtherPayload other_payload(uint8_t type, float focal_length_mm,
                                        const ros::Time& stamp);
// 3.3.3: only the percentage is pushed; the rest is NaN, discharging.
sensor_msgs::BatteryState battery_state(const psdk::BatteryInfoPush& p, const ros::Time& stamp);

// 3.7.1: one requested point of skyport/get_position, stamped with its UTC instant `time_ns`;
// missing from the answer or solution 0 ("not available"): no fix, NaN position. The altitude
// stays above sea level, as GetPosition.srv documents.
sensor_msgs::NavSatFix position_fix(const std::optional<psdk::TargetPosition>& point,
                                    int64_t time_ns, const std::string& frame);

}  // namespace k40t::driver::skyport
