#include "k40t_driver/ros/topic_publisher.h"

#include <utility>

#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/ros/job_status_conversions.h"

namespace k40t::driver {

namespace {
template <class T>
struct Tag {
  using type = T;
};

ros::Time to_ros(StampNs stamp) {
  ros::Time t;
  // Negative only with sim time before the first /clock (now = 0 minus the wire time).
  t.fromNSec(stamp > 0 ? static_cast<uint64_t>(stamp) : 0);
  return t;
}
}  // namespace

TopicPublisher::TopicPublisher(ros::NodeHandle nh, PodDriver& driver, const RosPodConfig& config)
    : nh_(nh), config_(config) {
  namespace p = protocol;
  const FrameIds& ids = config_.ids;

  joint_states_ = advertise<sensor_msgs::JointState>("joint_states");
  attitude_ = advertise<geometry_msgs::QuaternionStamped>("gimbal/attitude");
  driver.on<p::GimbalAttitude>(
      [this](const p::GimbalAttitude& m, StampNs s) { publish_attitude(m, s); });

  // One line per status topic: advertise, then convert and publish each report as it comes.
  auto forward = [&](auto tag, ros::Publisher& publisher, const std::string& topic, auto convert) {
    using Msg = typename decltype(tag)::type;
    using RosMsg = decltype(convert(std::declval<Msg>(), ros::Time()));
    publisher = advertise<RosMsg>(topic);
    driver.on<Msg>([&publisher, convert](const Msg& m, StampNs s) {
      publisher.publish(convert(m, to_ros(s)));
    });
  };
  auto plain = [](const auto& m, const ros::Time& t) { return to_msg(m, t); };
  forward(Tag<p::GimbalStatus>{}, gimbal_status_, "gimbal/status", plain);
  forward(Tag<p::CameraSystemStatus>{}, camera_status_, "camera/status", plain);
  forward(Tag<p::VisibleStatus>{}, visible_status_, "visible/status", plain);
  forward(Tag<p::PhotoStatus>{}, photo_status_, "photo/status", plain);
  forward(Tag<p::RecordStatus>{}, record_status_, "record/status", plain);
  // The long operations' status frames. Not "<action>/status": actionlib owns those names.
  forward(Tag<p::ZoomStatus>{}, zoom_status_, "zoom/status", plain);
  forward(Tag<p::PreciseReshootStatus>{}, reshoot_status_, "reshoot/status", plain);
  forward(Tag<p::TfCardUpgradeStatus>{}, tf_upgrade_status_, "tf_card_upgrade/status", plain);
  forward(Tag<p::SdFormatStatus>{}, sd_format_status_, "sd_format/status", plain);
  forward(Tag<p::CameraUpgradeStatus>{}, camera_upgrade_status_, "camera/upgrade_status", plain);
  forward(Tag<p::ThermalStatus>{}, thermal_stats_, "thermal/stats",
          [ids](const p::ThermalStatus& m, const ros::Time& t) { return to_msg(m, t, ids); });

  // Laser range: the single-ranging ACK (whoever asked) and the periodic status frame. A refusal
  // carries no distance and publishes nothing.
  laser_range_ = advertise<sensor_msgs::Range>("laser/range");
  auto publish_range = [this, ids, limits = config_.range](const auto& m, StampNs s) {
    if (m.code == p::ResponseCode::kOk)
      laser_range_.publish(to_range(m.distance_m, to_ros(s), ids, limits));
  };
  driver.on<p::LaserRangeAck>(publish_range);
  driver.on<p::LaserPeriodicRangeStatus>(publish_range);
  forward(
      Tag<p::TargetGpsAck>{}, laser_target_, "laser/target",
      [ids](const p::TargetGpsAck& m, const ros::Time& t) { return to_nav_sat_fix(m, t, ids); });

  // Raw frames. In replay mode raw/rx is the input (ReplayInput), not an output.
  if (!driver.replay()) {
    raw_rx_ = advertise<k40t_driver::Frame>("raw/rx", 100);
    raw_tx_ = advertise<k40t_driver::Frame>("raw/tx", 100);
    driver.on_rx_frame([this](const protocol::FrameView& f, StampNs s) {
      raw_rx_.publish(to_frame_msg(f.bytes, f.size, to_ros(s), k40t_driver::Frame::RX));
    });
    driver.on_tx_frame([this](const protocol::FrameView& f, StampNs s) {
      raw_tx_.publish(to_frame_msg(f.bytes, f.size, to_ros(s), k40t_driver::Frame::TX));
    });
  }

  if (config_.publish_tf) {
    tf_ = std::make_unique<tf2_ros::TransformBroadcaster>();
    static_tf_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
    static_tf_->sendTransform(sensor_transforms(ros::Time::now(), ids, config_.geometry));
  }
}

void TopicPublisher::publish_attitude(const protocol::GimbalAttitude& attitude, StampNs stamp) {
  const ros::Time t = to_ros(stamp);
  joint_states_.publish(to_joint_state(attitude, t, config_.ids));
  attitude_.publish(to_attitude(attitude, t, config_.ids));
  if (tf_) tf_->sendTransform(gimbal_transforms(attitude, t, config_.ids, config_.geometry));
}

}  // namespace k40t::driver
