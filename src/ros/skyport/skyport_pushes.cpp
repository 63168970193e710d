// The aircraft's data pushes (0x03) as ROS messages, and the pod fed from them (feed_pod).
#include <chrono>
#include <cmath>

#include <geometry_msgs/QuaternionStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <ros/console.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/NavSatFix.h>
#include <sensor_msgs/TimeReference.h>
#include <std_msgs/Float32.h>
#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>

#include "k40t_driver/BarometricAltitude.h"
#include "k40t_driver/LinkBandwidth.h"
#include "k40t_driver/OtherPayload.h"
#include "k40t_driver/UavState.h"
#include "k40t_driver/geo/geodesy.h"
#include "k40t_driver/psdk/commands/all.h"
#include "k40t_driver/psdk/commands/header_variants.h"
#include "k40t_driver/ros/skyport/skyport_ros.h"
#include "k40t_driver/skyport/position_request.h"
#include "k40t_driver/skyport/pps_rule.h"

namespace k40t::driver::skyport {

using namespace psdk;

namespace {

constexpr double kDegPerRad = 180.0 / M_PI;

ros::Time unix_time(const DateTime& t, uint32_t microsecond) {
  return ros::Time(static_cast<uint32_t>(std::max<int64_t>(unix_seconds(t), 0)),
                   microsecond * 1000);
}

// NED velocity in cm/s -> ENU m/s.
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

// `altitude_msl_m`: the PSDK pushes heights above sea level (3.3.8, 3.3.9); NavSatFix wants the
// WGS 84 ellipsoid's (docs/geo.md), so the EGM96 undulation is added. NaN stays NaN (unknown),
// and so does a height the geoid cannot convert.
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

}  // namespace

void SkyportRos::register_pushes() {
  session_->handle<AttitudePush>([this](const AttitudePush& p) {
    const ros::Time now = ros::Time::now();
    geometry_msgs::QuaternionStamped q;  // as pushed: body (FRD) -> NED
    q.header.stamp = now;
    q.header.frame_id = "ned";
    q.quaternion.w = p.q0;
    q.quaternion.x = p.q1;
    q.quaternion.y = p.q2;
    q.quaternion.z = p.q3;
    attitude_.publish(q);
    // REP 103: base_link (FLU) in ENU. Same roll, pitch negated, yaw from east counter-clockwise.
    double roll = 0, pitch = 0, yaw = 0;
    tf2::Matrix3x3(tf2::Quaternion(p.q1, p.q2, p.q3, p.q0).normalized()).getRPY(roll, pitch, yaw);
    tf2::Quaternion enu;
    enu.setRPY(roll, -pitch, M_PI / 2 - yaw);
    sensor_msgs::Imu imu;
    imu.header.stamp = now;
    imu.header.frame_id = config_.base_frame;
    imu.orientation.x = enu.x();
    imu.orientation.y = enu.y();
    imu.orientation.z = enu.z();
    imu.orientation.w = enu.w();
    imu.angular_velocity_covariance[0] = -1;  // not pushed
    imu.linear_acceleration_covariance[0] = -1;
    imu_.publish(imu);
    if (config_.feed_pod) feed_attitude_.publish(imu);
  });
  session_->handle<GpsPush>([this](const GpsPush& p) {
    const ros::Time now = ros::Time::now();
    // The fused position carries only the height above take-off: altitude unknown (NaN).
    gps_.publish(fix_message(now, config_.world_frame, p.latitude_rad * kDegPerRad,
                             p.longitude_rad * kDegPerRad, std::nan(""),
                             p.signal == GpsSignal::kNone ? sensor_msgs::NavSatStatus::STATUS_NO_FIX
                                                          : sensor_msgs::NavSatStatus::STATUS_FIX));
    std_msgs::Float32 height;
    height.data = static_cast<float>(p.relative_height_m);
    relative_height_.publish(height);
  });
  session_->handle<RawGpsPush>([this](const RawGpsPush& p) {
    const ros::Time now = ros::Time::now();
    sensor_msgs::NavSatFix fix =
        fix_message(now, config_.world_frame, p.latitude_deg, p.longitude_deg, p.height_m,
                    p.fix_state >= 3 ? sensor_msgs::NavSatStatus::STATUS_FIX
                                     : sensor_msgs::NavSatStatus::STATUS_NO_FIX);
    const double h = p.horizontal_accuracy_mm / 1000.0, v = p.vertical_accuracy_mm / 1000.0;
    fix.position_covariance = {h * h, 0, 0, 0, h * h, 0, 0, 0, v * v};
    fix.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_DIAGONAL_KNOWN;
    raw_gps_.publish(fix);
    raw_gps_velocity_.publish(enu_velocity(now, config_.world_frame, p.velocity_north_cm_s,
                                           p.velocity_east_cm_s, p.velocity_down_cm_s));
    if (config_.feed_pod && config_.feed_fix == "raw_gps") feed_fix_.publish(fix);
  });
  session_->handle<RawRtkPush>([this](const RawRtkPush& p) {
    const ros::Time now = ros::Time::now();
    // Position type 0: no solution; 50 (narrow integer): RTK fixed (DJI's numbering).
    const int8_t status = p.position_type == 0    ? sensor_msgs::NavSatStatus::STATUS_NO_FIX
                          : p.position_type >= 50 ? sensor_msgs::NavSatStatus::STATUS_GBAS_FIX
                                                  : sensor_msgs::NavSatStatus::STATUS_FIX;
    const sensor_msgs::NavSatFix fix =
        fix_message(now, config_.world_frame, p.latitude_deg, p.longitude_deg, p.height_m, status);
    rtk_.publish(fix);
    rtk_velocity_.publish(enu_velocity(now, config_.world_frame, p.velocity_north_cm_s,
                                       p.velocity_east_cm_s, p.velocity_down_cm_s));
    if (config_.feed_pod && config_.feed_fix == "rtk") feed_fix_.publish(fix);
  });
  session_->handle<UavStatePush>([this](const UavStatePush& p) {
    k40t_driver::UavState out;
    out.header.stamp = ros::Time::now();
    out.compass_abnormal = p.state.compass_abnormal;
    out.motors_rotating = p.state.motors_rotating;
    out.landing = static_cast<uint8_t>(p.state.landing);
    out.flight_time_s = static_cast<float>(p.flight_time_s);
    out.drone_type = static_cast<uint8_t>(p.drone_type);
    const char* text = to_string(p.drone_type);
    out.drone_type_text = text ? text : "unknown";
    uav_state_.publish(out);
  });
  // 3.3.1 in either length: 42 bytes (document) or 33 (DJI's V1.0.0, no OSDK fields; P31).
  session_->on_command(
      LinkBandwidthPush::key(), [this](const IncomingCommand& in) -> std::optional<Data> {
        bool has_osdk = false;
        const Result<LinkBandwidthPush> push =
            decode_link_bandwidth(in.data.data(), in.data.size, &has_osdk);
        if (!push) {
          session_->note_decode_error();
          return std::nullopt;  // pushes get no ACK
        }
        const LinkBandwidthPush& p = push.value();
        k40t_driver::LinkBandwidth out;
        out.header.stamp = ros::Time::now();
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
        out.osdk_uplink_bytes_s = p.osdk_uplink_bytes_s;  // 0 when the push had no OSDK fields
        link_.publish(out);
        return std::nullopt;
      });
  session_->handle<BarometricAltitudePush>([this](const BarometricAltitudePush& p) {
    k40t_driver::BarometricAltitude out;
    out.header.stamp = ros::Time::now();
    out.altitude_m = p.altitude_m;
    baro_.publish(out);
  });
  session_->handle<AppDateTimePush>([this](const AppDateTimePush& p) {
    sensor_msgs::TimeReference out;
    out.header.stamp = ros::Time::now();
    out.time_ref = unix_time(p.time, 0);
    out.source = "dji_app";
    app_time_.publish(out);
  });
  session_->handle<UtcTimePush>([this](const UtcTimePush& p) {
    // Sent once per PPS pulse: the UTC time of the pulse, received just after it. A field out of
    // range (a microsecond beyond 999999 would overflow the stamp) drops the push.
    const Status valid = validate(p);
    if (!valid) {
      ++utc_pushes_invalid_;
      ROS_WARN_THROTTLE(5.0, "SKYPORT UTC time push dropped: %s", valid.message().c_str());
      return;
    }
    const ros::Time received = ros::Time::now();
    sensor_msgs::TimeReference out;
    out.time_ref = unix_time(p.time, p.microsecond);
    if (config_.pps_topic.empty()) {
      // No PPS edge to measure against: the rule relative to the most punctual push (pps_rule.h).
      const double steady_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
              .count();
      const UtcPushLateness::Judgement lateness =
          utc_lateness_.judge(out.time_ref.toSec(), steady_s);
      if (lateness.verdict != UtcPushVerdict::kUse) {  // 3.3.10: surely over 500 ms after its edge
        ++utc_pushes_late_;
        return;
      }
      ++utc_pushes_unchecked_;
      // Its edge was at least the excess delay before its receipt.
      out.header.stamp = received - ros::Duration(lateness.excess_delay_s);
    } else {
      std::optional<ros::Time> edge;
      {
        std::lock_guard<std::mutex> lock(mutex_);
        edge = last_pps_edge_;
      }
      const UtcPushVerdict verdict = judge_utc_push(
          edge ? std::optional<double>(edge->toSec()) : std::nullopt, received.toSec());
      if (verdict != UtcPushVerdict::kUse) {  // 3.3.10: more than 500 ms after its edge
        ++utc_pushes_late_;
        return;
      }
      out.header.stamp = *edge;  // the instant the UTC time describes, on this computer's clock
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      newest_utc_ns_ = static_cast<int64_t>(out.time_ref.toNSec());
    }
    out.source = "skyport_pps";
    utc_time_.publish(out);
    if (config_.feed_pod) feed_time_.publish(out);
  });
  const auto publish_other = [this] {
    k40t_driver::OtherPayload out;
    out.header.stamp = ros::Time::now();
    out.type = other_payload_type_;
    const char* text = to_string(static_cast<OtherPayloadType>(other_payload_type_));
    out.type_text = text ? text : "unknown";
    out.focal_length_mm = other_payload_focal_mm_;
    other_payload_.publish(out);
  };
  session_->handle<OtherPayloadTypePush>([this, publish_other](const OtherPayloadTypePush& p) {
    other_payload_type_ = static_cast<uint8_t>(p.type);
    publish_other();
  });
  session_->handle<OtherPayloadFocalLengthPush>(
      [this, publish_other](const OtherPayloadFocalLengthPush& p) {
        other_payload_focal_mm_ = static_cast<float>(p.focal_length_mm);
        publish_other();
      });
}

}  // namespace k40t::driver::skyport
