// The aircraft's data pushes (0x03) published as ROS messages (push_conversions.h), the UTC push's
// 500 ms rule (pps_rule.h), and the pod fed from them (feed_pod).
#include <chrono>
#include <optional>
#include <string>
#include <utility>

#include <ros/console.h>
#include <std_msgs/Float32.h>

#include "k40t_driver/psdk/commands/all.h"
#include "k40t_driver/psdk/commands/header_variants.h"
#include "k40t_driver/ros/skyport/push_conversions.h"
#include "k40t_driver/ros/skyport/skyport_ros.h"
#include "k40t_driver/skyport/pps_rule.h"

namespace k40t::driver::skyport {

using namespace psdk;

template <class Push, class Convert>
void SkyportRos::forward(ros::Publisher& publisher, const std::string& topic, Convert convert) {
  using Msg = decltype(convert(std::declval<const Push&>(), ros::Time()));
  publisher = nh_.advertise<Msg>(topic, 10);
  session_->handle<Push>(
      [&publisher, convert](const Push& p) { publisher.publish(convert(p, ros::Time::now())); });
}

void SkyportRos::register_pushes() {
  session_->handle<AttitudePush>([this](const AttitudePush& p) {
    const ros::Time now = ros::Time::now();
    attitude_.publish(ned_attitude(p, now));
    const sensor_msgs::Imu imu = enu_attitude(p, now, config_.base_frame);
    imu_.publish(imu);
    if (config_.feed_pod) feed_attitude_.publish(imu);
  });
  session_->handle<GpsPush>([this](const GpsPush& p) {
    gps_.publish(gps_fix(p, ros::Time::now(), config_.world_frame));
    std_msgs::Float32 height;
    height.data = static_cast<float>(p.relative_height_m);
    relative_height_.publish(height);
  });
  // A receiver's push (raw GPS, RTK): its fix and velocity, and the fix fed to the pod when
  // ~feed_fix names the receiver.
  const auto receiver = [this](const char* name, ros::Publisher& fix_topic,
                               ros::Publisher& velocity_topic, auto to_fix, auto to_velocity) {
    return [this, name, &fix_topic, &velocity_topic, to_fix, to_velocity](const auto& p) {
      const ros::Time now = ros::Time::now();
      const sensor_msgs::NavSatFix fix = to_fix(p, now, config_.world_frame);
      fix_topic.publish(fix);
      velocity_topic.publish(to_velocity(p, now, config_.world_frame));
      if (config_.feed_pod && config_.feed_fix == name) feed_fix_.publish(fix);
    };
  };
  session_->handle<RawGpsPush>(
      receiver("raw_gps", raw_gps_, raw_gps_velocity_, raw_gps_fix, raw_gps_velocity));
  session_->handle<RawRtkPush>(receiver("rtk", rtk_, rtk_velocity_, rtk_fix, rtk_velocity));
  forward<UavStatePush>(uav_state_, "skyport/uav_state", uav_state);
  // 3.3.1 in either length: 42 bytes (document) or 33 (DJI's V1.0.0, no OSDK fields; P31).
  session_->on_command(LinkBandwidthPush::key(),
                       [this](const IncomingCommand& in) -> std::optional<Data> {
                         bool has_osdk = false;
                         const Result<LinkBandwidthPush> push =
                             decode_link_bandwidth(in.data.data(), in.data.size, &has_osdk);
                         if (!push) {
                           session_->note_decode_error();
                           return std::nullopt;  // pushes get no ACK
                         }
                         link_.publish(link_bandwidth(push.value(), ros::Time::now()));
                         return std::nullopt;
                       });
  forward<BarometricAltitudePush>(baro_, "skyport/barometric_altitude", barometric_altitude);
  forward<AppDateTimePush>(app_time_, "skyport/app_time", app_time);
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
    const ros::Time utc = unix_time(p.time, p.microsecond);
    ros::Time edge_stamp;  // the instant the UTC time describes, on this computer's clock
    if (config_.pps_topic.empty()) {
      // No PPS edge to measure against: the rule relative to the most punctual push (pps_rule.h).
      const double steady_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch())
              .count();
      const UtcPushLateness::Judgement lateness = utc_lateness_.judge(utc.toSec(), steady_s);
      if (lateness.verdict != UtcPushVerdict::kUse) {  // 3.3.10: surely over 500 ms after its edge
        ++utc_pushes_late_;
        return;
      }
      ++utc_pushes_unchecked_;
      // Its edge was at least the excess delay before its receipt.
      edge_stamp = received - ros::Duration(lateness.excess_delay_s);
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
      edge_stamp = *edge;
    }
    positions_.synchronised(static_cast<int64_t>(utc.toNSec()));
    const sensor_msgs::TimeReference out = utc_time(p, edge_stamp);
    utc_time_.publish(out);
    if (config_.feed_pod) feed_time_.publish(out);
  });
  const auto publish_other = [this] {
    other_payload_.publish(
        other_payload(other_payload_type_, other_payload_focal_mm_, ros::Time::now()));
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
