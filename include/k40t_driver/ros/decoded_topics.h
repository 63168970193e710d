// The one place that says which topic each decoded message goes to: joint_states, attitude and TF
// from the attitude report, the status messages, laser range and target. Written once for any
// "sink", so that the live driver (TopicPublisher: ros::Publisher) and the offline decoder
// (`k40t bag`: rosbag::Bag::write) publish the same messages from the same frames and cannot
// drift apart. A topic added here appears in both.
//
// A Sink provides
//   template <class RosMsg> std::function<void(const RosMsg&)> advertise(topic, queue, latch);
// topics are relative to the driver's namespace unless they start with '/'.
// Handlers are registered on the PodDriver (before PodDriver::start()); they only convert and
// publish, with the frame's stamp (PodDriver), so a replay publishes what the live run did.
#pragma once

#include <functional>
#include <string>
#include <utility>

#include <tf2_msgs/TFMessage.h>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/ros/conversions.h"
#include "k40t_driver/ros/geo_glue.h"
#include "k40t_driver/ros/job_status_conversions.h"
#include "k40t_driver/ros/ros_params.h"

namespace k40t::driver {

namespace decoded_topics_detail {
template <class T>
struct Tag {
  using type = T;
};
}  // namespace decoded_topics_detail

inline ros::Time to_ros_time(StampNs stamp) {
  ros::Time t;
  // Negative only with sim time before the first /clock (now = 0 minus the wire time).
  t.fromNSec(stamp > 0 ? static_cast<uint64_t>(stamp) : 0);
  return t;
}

// The TF broadcaster's topic and queue (tf2_ros::TransformBroadcaster).
constexpr const char* kTfTopic = "/tf";
constexpr uint32_t kTfQueue = 100;

template <class Sink>
void advertise_decoded_topics(Sink& sink, PodDriver& driver, const RosPodConfig& config) {
  namespace p = protocol;
  using decoded_topics_detail::Tag;
  const FrameIds ids = config.ids;

  // The attitude report: joint states, the stabilised attitude, and TF.
  {
    auto joints = sink.template advertise<sensor_msgs::JointState>("joint_states", 10, false);
    auto attitude =
        sink.template advertise<geometry_msgs::QuaternionStamped>("gimbal/attitude", 10, false);
    std::function<void(const tf2_msgs::TFMessage&)> tf;
    if (config.publish_tf)
      tf = sink.template advertise<tf2_msgs::TFMessage>(kTfTopic, kTfQueue, false);
    driver.on<p::GimbalAttitude>(
        [=, geometry = config.geometry, order = driver.codec().conventions.attitude_order](
            const p::GimbalAttitude& m, StampNs s) {
          const ros::Time t = to_ros_time(s);
          joints(to_joint_state(m, t, ids));
          attitude(to_attitude(m, t, ids, order));
          if (tf) {
            tf2_msgs::TFMessage transforms;  // what TransformBroadcaster::sendTransform publishes
            transforms.transforms = gimbal_transforms(m, t, ids, geometry);
            tf(transforms);
          }
        });
  }

  // One line per status topic: advertise, then convert and publish each report as it comes.
  auto forward = [&](auto tag, const std::string& topic, auto convert) {
    using Msg = typename decltype(tag)::type;
    using RosMsg = decltype(convert(std::declval<Msg>(), ros::Time()));
    auto publish = sink.template advertise<RosMsg>(topic, 10, false);
    driver.on<Msg>(
        [publish, convert](const Msg& m, StampNs s) { publish(convert(m, to_ros_time(s))); });
  };
  auto plain = [](const auto& m, const ros::Time& t) { return to_msg(m, t); };
  forward(Tag<p::GimbalStatus>{}, "gimbal/status", plain);
  forward(Tag<p::CameraSystemStatus>{}, "camera/status", plain);
  // The shutter as the pod's reading says (shutter_field: 16 bits of us cannot carry 1/4 s).
  forward(Tag<p::VisibleStatus>{}, "visible/status",
          [field = driver.codec().conventions.shutter_field](const p::VisibleStatus& m,
                                                             const ros::Time& t) {
            k40t_driver::VisibleStatus msg = to_msg(m, t);
            msg.shutter_s = static_cast<float>(p::shutter_us_from_wire(m.shutter_us, field) * 1e-6);
            return msg;
          });
  forward(Tag<p::PhotoStatus>{}, "photo/status", plain);
  forward(Tag<p::RecordStatus>{}, "record/status", plain);
  // The long operations' status frames. Not "<action>/status": actionlib owns those names.
  forward(Tag<p::ZoomStatus>{}, "zoom/status", plain);
  forward(Tag<p::PreciseReshootStatus>{}, "reshoot/status", plain);
  forward(Tag<p::TfCardUpgradeStatus>{}, "tf_card_upgrade/status", plain);
  forward(Tag<p::SdFormatStatus>{}, "sd_format/status", plain);
  forward(Tag<p::CameraUpgradeStatus>{}, "camera/upgrade_status", plain);
  forward(Tag<p::ThermalStatus>{}, "thermal/stats",
          [ids](const p::ThermalStatus& m, const ros::Time& t) { return to_msg(m, t, ids); });

  // Laser range: the single-ranging ACK (whoever asked) and the periodic status frame. A refusal
  // carries no distance and publishes nothing.
  auto range = sink.template advertise<sensor_msgs::Range>("laser/range", 10, false);
  auto publish_range = [range, ids, limits = config.range](const auto& m, StampNs s) {
    if (m.code == p::ResponseCode::kOk) range(to_range(m.distance_m, to_ros_time(s), ids, limits));
  };
  driver.on<p::LaserRangeAck>(publish_range);
  driver.on<p::LaserPeriodicRangeStatus>(publish_range);
  // The laser target (0x010320): its position, and every field of the answer (docs/geo.md); both
  // carry the same covariance, approximated from the vehicle state at the answer's time.
  auto target = sink.template advertise<sensor_msgs::NavSatFix>("laser/target", 10, false);
  auto report = sink.template advertise<k40t_driver::LaserTarget>("laser/target_report", 10, false);
  driver.on<p::TargetGpsAck>([target, report, ids, &driver](const p::TargetGpsAck& m, StampNs s) {
    const ros::Time t = to_ros_time(s);
    // An OK answer at 0 deg, 0 deg is "no return" unless the pod says otherwise
    // (laser_target_zeros, docs/protocol/decisions.md#conventions).
    const p::LaserTargetZeros zeros = driver.codec().conventions.laser_target_zeros;
    const k40t_driver::LaserTarget full =
        to_laser_target(m, t, ids.laser, driver.vehicle_state_at(s), zeros);
    target(to_nav_sat_fix(m, t, ids, full.position_covariance, zeros));
    report(full);
  });
}

}  // namespace k40t::driver
