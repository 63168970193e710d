#include "k40t_driver/ros/skyport/skyport_ros.h"

#include <cmath>
#include <cstdio>
#include <ctime>

#include <geometry_msgs/QuaternionStamped.h>
#include <geometry_msgs/TwistStamped.h>
#include <ros/console.h>
#include <sensor_msgs/BatteryState.h>
#include <sensor_msgs/Imu.h>
#include <sensor_msgs/NavSatFix.h>
#include <sensor_msgs/TimeReference.h>
#include <std_msgs/Bool.h>
#include <std_msgs/Float32.h>

#include "k40t_driver/BarometricAltitude.h"
#include "k40t_driver/LinkBandwidth.h"
#include "k40t_driver/OtherPayload.h"
#include "k40t_driver/UavState.h"
#include "k40t_driver/psdk/commands/all.h"
#include "k40t_driver/ros/skyport/push_conversions.h"
#include "k40t_driver/skyport/link_health.h"
#include "k40t_driver/skyport/transparent_chunks.h"
#include "k40t_driver/transport/device_url.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::driver::skyport {

using namespace psdk;

Result<std::unique_ptr<SkyportRos>> SkyportRos::create(ros::NodeHandle nh,
                                                       ros::NodeHandle private_nh) {
  Result<SkyportConfig> config = read_skyport_config(private_nh);
  if (!config) return Result<std::unique_ptr<SkyportRos>>::fail(config.error());
  auto link =
      transport::make_transport(transport::device_url_with_baud(config->device, config->baud));
  if (!link) return Result<std::unique_ptr<SkyportRos>>::fail(link.error());
  SessionOptions options;
  options.role = Sender::kPayload;
  options.ack_timeout = std::chrono::milliseconds(std::lround(config->ack_timeout_s * 1000));
  if (config->encryption) options.aes_key = derive_aes_key(config->credentials);
  auto session = std::make_unique<Session>(std::move(link.value()), options);
  std::unique_ptr<SkyportRos> ros_side(
      new SkyportRos(nh, private_nh, config.value(), std::move(session)));
  const Status started = ros_side->session_->start();
  if (!started) return Result<std::unique_ptr<SkyportRos>>::fail(started.message());
  ROS_INFO("SKYPORT bridge on %s (AES %s)", config->device.c_str(),
           config->encryption ? "on" : "off");
  return ros_side;
}

SkyportRos::SkyportRos(ros::NodeHandle nh, ros::NodeHandle private_nh, SkyportConfig config,
                       std::unique_ptr<Session> session)
    : nh_(nh),
      private_nh_(private_nh),
      config_(std::move(config)),
      session_(std::move(session)),
      positions_(*session_, config_.position_min_interval_s),
      diagnostics_(nh, private_nh) {
  advertise();
  pod_ = std::make_unique<RosPodPort>(nh_, config_.reconfigure, config_.service_timeout_s,
                                      [this](const std::string& text) {
                                        // Pod events become floating-window messages (subscriptions
                                        // may fire before the bridge exists: those early events are
                                        // dropped).
                                        if (SkyportBridge* bridge = bridge_ptr_.load())
                                          bridge->floating_window(text);
                                      });
  bridge_ = std::make_unique<SkyportBridge>(
      *session_, *pod_, config_.bridge,
      [this](const BatteryInfoPush& push) {
        battery_.publish(battery_state(push, ros::Time::now()));
        std::lock_guard<std::mutex> lock(mutex_);
        if (!power_off_soon_ || *power_off_soon_ != push.power_off_soon) {
          power_off_soon_ = push.power_off_soon;
          std_msgs::Bool warning;
          warning.data = push.power_off_soon;
          power_off_.publish(warning);
          if (push.power_off_soon) ROS_WARN("SKYPORT: the aircraft announces power-off");
        }
      },
      [](const std::string& text) { ROS_WARN("%s", text.c_str()); });
  bridge_ptr_ = bridge_.get();
  register_pushes();
  register_transparent();
  publish_handled_commands();
  session_->on_frame([this](const FrameView&) {
    std::lock_guard<std::mutex> lock(mutex_);
    last_frame_ = std::chrono::steady_clock::now();
  });
  get_position_ = nh_.advertiseService("skyport/get_position", &SkyportRos::on_get_position, this);
  diagnostics_.setHardwareID(config_.device);
  diagnostics_.add("SKYPORT link", this, &SkyportRos::diagnose);
  diagnostic_timer_ =
      nh_.createTimer(ros::Duration(config_.diagnostic_period_s),
                      [this](const ros::TimerEvent&) { diagnostics_.force_update(); });
}

SkyportRos::~SkyportRos() {
  // The diagnostics timer and the link stop first: no callback may run into a half-destroyed glue.
  diagnostic_timer_.stop();
  session_->stop();
  bridge_ptr_ = nullptr;  // pod events no longer reach the bridge
  bridge_.reset();        // joins its worker, which may still be calling the pod
  pod_.reset();
}

void SkyportRos::advertise() {
  attitude_ = nh_.advertise<geometry_msgs::QuaternionStamped>("skyport/attitude", 10);
  imu_ = nh_.advertise<sensor_msgs::Imu>("skyport/imu", 10);
  gps_ = nh_.advertise<sensor_msgs::NavSatFix>("skyport/gps", 10);
  relative_height_ = nh_.advertise<std_msgs::Float32>("skyport/gps/relative_height", 10);
  raw_gps_ = nh_.advertise<sensor_msgs::NavSatFix>("skyport/raw_gps", 10);
  raw_gps_velocity_ = nh_.advertise<geometry_msgs::TwistStamped>("skyport/raw_gps/velocity", 10);
  rtk_ = nh_.advertise<sensor_msgs::NavSatFix>("skyport/rtk", 10);
  rtk_velocity_ = nh_.advertise<geometry_msgs::TwistStamped>("skyport/rtk/velocity", 10);
  battery_ = nh_.advertise<sensor_msgs::BatteryState>("skyport/battery", 10);
  power_off_ = nh_.advertise<std_msgs::Bool>("skyport/power_off_warning", 1, true);
  link_ = nh_.advertise<k40t_driver::LinkBandwidth>("skyport/link_bandwidth", 10);
  utc_time_ = nh_.advertise<sensor_msgs::TimeReference>("skyport/utc_time", 10);
  other_payload_ = nh_.advertise<k40t_driver::OtherPayload>("skyport/other_payload", 10, true);
  from_mobile_ = nh_.advertise<std_msgs::UInt8MultiArray>("skyport/transparent/from_mobile", 10);
  from_onboard_ = nh_.advertise<std_msgs::UInt8MultiArray>("skyport/transparent/from_onboard", 10);
  if (config_.feed_pod) {
    feed_fix_ = nh_.advertise<sensor_msgs::NavSatFix>("fix", 10);
    feed_attitude_ = nh_.advertise<sensor_msgs::Imu>("attitude", 10);
    feed_time_ = nh_.advertise<sensor_msgs::TimeReference>("time_reference", 10);
  }
  if (!config_.pps_topic.empty()) {
    pps_ = nh_.subscribe<sensor_msgs::TimeReference>(
        config_.pps_topic, 10, [this](const sensor_msgs::TimeReference::ConstPtr& edge) {
          std::lock_guard<std::mutex> lock(mutex_);
          last_pps_edge_ = edge->header.stamp;
        });
  }
  to_mobile_ = nh_.subscribe("skyport/transparent/to_mobile", 10, &SkyportRos::on_to_mobile, this);
  to_onboard_ =
      nh_.subscribe("skyport/transparent/to_onboard", 10, &SkyportRos::on_to_onboard, this);
}

void SkyportRos::publish_handled_commands() {
  std::vector<std::string> keys;
  for (const CommandKey key : session_->handled_commands()) {
    char text[16];
    std::snprintf(text, sizeof(text), "0x%02X/0x%02X", key.set, key.id);
    keys.emplace_back(text);
  }
  private_nh_.setParam("handled_commands", keys);
}

void SkyportRos::register_transparent() {
  const auto forward = [](ros::Publisher& pub) {
    return [&pub](const IncomingCommand& in) -> std::optional<Data> {
      std_msgs::UInt8MultiArray out;
      out.data.assign(in.data.data(), in.data.data() + in.data.size);
      pub.publish(out);
      return std::nullopt;  // not ACKed (3.2.1, 3.6.1)
    };
  };
  session_->on_command(TransparentFromMobile::key(), forward(from_mobile_));
  session_->on_command(TransparentFromOnboard::key(), forward(from_onboard_));
}

namespace {
// Sends `bytes` in pieces of at most `chunk` (the command's DATA limit; transparent_chunks.h).
void send_chunks(Session& session, CommandKey key, const std::vector<uint8_t>& bytes,
                 size_t chunk) {
  for (const ByteSpan piece : transparent_chunks(bytes.size(), chunk)) {
    const Status sent = session.send_raw(key, bytes.data() + piece.offset, piece.size);
    if (!sent) {
      ROS_WARN_THROTTLE(5.0, "SKYPORT transparent data: %s", sent.message().c_str());
      return;
    }
  }
}
}  // namespace

void SkyportRos::on_to_mobile(const std_msgs::UInt8MultiArray::ConstPtr& msg) {
  send_chunks(*session_, TransparentToMobile::key(), msg->data, kMaxTransparentToMobile);
}

void SkyportRos::on_to_onboard(const std_msgs::UInt8MultiArray::ConstPtr& msg) {
  send_chunks(*session_, TransparentToOnboard::key(), msg->data, kMaxOsdkTransparent);
}

void SkyportRos::diagnose(diagnostic_updater::DiagnosticStatusWrapper& status) {
  const SessionStats s = session_->stats();
  const BridgeStats b = bridge_->stats();
  double silent_s = -1;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (last_frame_)
      silent_s =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - *last_frame_).count();
  }
  const double pod_age_s = pod_->snapshot().state_age_s;
  const transport::LinkState link = session_->link_state();
  LinkHealthInput in;
  in.link = link;
  in.silent_s = silent_s;
  in.silence_timeout_s = config_.silence_timeout_s;
  in.bridge = b;
  in.pod_age_s = pod_age_s;
  in.pod_stale_s = config_.pod_stale_s;
  const LinkHealth health = link_health(in);
  const bool pod_stale = health.pod_stale;
  status.summary(health.level == HealthLevel::kError  ? diagnostic_msgs::DiagnosticStatus::ERROR
                 : health.level == HealthLevel::kWarn ? diagnostic_msgs::DiagnosticStatus::WARN
                                                      : diagnostic_msgs::DiagnosticStatus::OK,
                 health.summary);
  status.add("link", transport::to_string(link));
  status.add("seconds since last frame", silent_s);
  status.add("identity verifications answered", b.identity_requests);
  status.add("identity verifications refused", b.identity_refused);
  status.add("good frames", s.parser.frames_good);
  status.add("header CRC errors", s.parser.header_crc_errors);
  status.add("frame CRC errors", s.parser.frame_crc_errors);
  status.add("length errors", s.parser.length_errors);
  status.add("discarded bytes", s.parser.bytes_discarded);
  status.add("sequence gaps", s.parser.sequence_gaps);
  status.add("commands received", s.commands_received);
  status.add("unsupported commands", s.unsupported);
  status.add("decode errors", s.decode_errors);
  status.add("decrypt errors", s.decrypt_errors);
  status.add("pod calls", b.pod_calls);
  status.add("pod call failures", b.pod_call_failures);
  status.add("power-off ready", b.power_off_ready);
  status.add("invalid commands refused", b.invalid_commands);
  status.add("busy answers (work queue full)", b.busy_answers);
  status.add("pod jobs queued", b.queued_jobs);
  status.add("pod state age (s)", pod_age_s);
  status.add("pod state stale", pod_stale);
  status.add("UTC pushes dropped (invalid)", utc_pushes_invalid_.load());
  status.add("UTC pushes dropped (over 500 ms after their edge)", utc_pushes_late_.load());
  status.add("UTC pushes used without PPS (checked against the most punctual)",
             utc_pushes_unchecked_.load());
}

}  // namespace k40t::driver::skyport
