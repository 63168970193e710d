#include "k40t_driver/ros/skyport/skyport_ros.h"

#include <cmath>
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
#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>

#include "k40t_driver/BarometricAltitude.h"
#include "k40t_driver/LinkBandwidth.h"
#include "k40t_driver/OtherPayload.h"
#include "k40t_driver/UavState.h"
#include "k40t_driver/psdk/commands/all.h"
#include "k40t_driver/ros/pod_driver.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::driver::skyport {

using namespace psdk;

namespace {

constexpr double kDegPerRad = 180.0 / M_PI;

ros::Time unix_time(const DateTime& t, uint32_t microsecond) {
  std::tm tm{};
  tm.tm_year = t.year - 1900;
  tm.tm_mon = t.month - 1;
  tm.tm_mday = t.day;
  tm.tm_hour = t.hour;
  tm.tm_min = t.minute;
  tm.tm_sec = t.second;
  const time_t seconds = timegm(&tm);
  return ros::Time(static_cast<uint32_t>(std::max<time_t>(seconds, 0)), microsecond * 1000);
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

sensor_msgs::NavSatFix fix_message(const ros::Time& stamp, const std::string& frame,
                                   double latitude_deg, double longitude_deg, double altitude_m,
                                   int8_t status) {
  sensor_msgs::NavSatFix fix;
  fix.header.stamp = stamp;
  fix.header.frame_id = frame;
  fix.latitude = latitude_deg;
  fix.longitude = longitude_deg;
  fix.altitude = altitude_m;
  fix.status.status = status;
  fix.status.service = sensor_msgs::NavSatStatus::SERVICE_GPS;
  fix.position_covariance_type = sensor_msgs::NavSatFix::COVARIANCE_TYPE_UNKNOWN;
  return fix;
}

}  // namespace

Result<std::unique_ptr<SkyportRos>> SkyportRos::create(ros::NodeHandle nh,
                                                       ros::NodeHandle private_nh) {
  Result<SkyportConfig> config = read_skyport_config(private_nh);
  if (!config) return Result<std::unique_ptr<SkyportRos>>::fail(config.error());
  auto link = transport::make_transport(device_url_with_baud(config->device, config->baud));
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
        sensor_msgs::BatteryState battery;
        battery.header.stamp = ros::Time::now();
        battery.percentage = push.percentage / 100.0f;
        battery.voltage = battery.current = battery.charge = battery.capacity = std::nanf("");
        battery.design_capacity = std::nanf("");
        battery.present = true;
        battery.power_supply_status = sensor_msgs::BatteryState::POWER_SUPPLY_STATUS_DISCHARGING;
        battery_.publish(battery);
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
  uav_state_ = nh_.advertise<k40t_driver::UavState>("skyport/uav_state", 10);
  link_ = nh_.advertise<k40t_driver::LinkBandwidth>("skyport/link_bandwidth", 10);
  baro_ = nh_.advertise<k40t_driver::BarometricAltitude>("skyport/barometric_altitude", 10);
  app_time_ = nh_.advertise<sensor_msgs::TimeReference>("skyport/app_time", 10);
  utc_time_ = nh_.advertise<sensor_msgs::TimeReference>("skyport/utc_time", 10);
  other_payload_ = nh_.advertise<k40t_driver::OtherPayload>("skyport/other_payload", 10, true);
  from_mobile_ = nh_.advertise<std_msgs::UInt8MultiArray>("skyport/transparent/from_mobile", 10);
  from_onboard_ = nh_.advertise<std_msgs::UInt8MultiArray>("skyport/transparent/from_onboard", 10);
  if (config_.feed_pod) {
    feed_fix_ = nh_.advertise<sensor_msgs::NavSatFix>("fix", 10);
    feed_attitude_ = nh_.advertise<sensor_msgs::Imu>("attitude", 10);
    feed_time_ = nh_.advertise<sensor_msgs::TimeReference>("time_reference", 10);
  }
  to_mobile_ = nh_.subscribe("skyport/transparent/to_mobile", 10, &SkyportRos::on_to_mobile, this);
  to_onboard_ =
      nh_.subscribe("skyport/transparent/to_onboard", 10, &SkyportRos::on_to_onboard, this);
}

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
  session_->handle<LinkBandwidthPush>([this](const LinkBandwidthPush& p) {
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
    out.osdk_uplink_bytes_s = p.osdk_uplink_bytes_s;
    link_.publish(out);
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
    // Sent once per PPS pulse: the UTC time of the pulse, received just after it.
    sensor_msgs::TimeReference out;
    out.header.stamp = ros::Time::now();
    out.time_ref = unix_time(p.time, p.microsecond);
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
// Sends `bytes` in pieces of at most `chunk` (the command's DATA limit).
void send_chunks(Session& session, CommandKey key, const std::vector<uint8_t>& bytes,
                 size_t chunk) {
  for (size_t at = 0; at < bytes.size(); at += chunk) {
    const Status sent =
        session.send_raw(key, bytes.data() + at, std::min(chunk, bytes.size() - at));
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

bool SkyportRos::on_get_position(k40t_driver::GetPosition::Request& req,
                                 k40t_driver::GetPosition::Response& res) {
  GetPosition request;
  if (req.time_offsets_us.empty() || req.time_offsets_us.size() > 4) {
    res.message = "time_offsets_us: 1..4 points, got " + std::to_string(req.time_offsets_us.size());
    return true;
  }
  const std::time_t base = static_cast<std::time_t>(req.base_time.sec);
  std::tm tm{};
  gmtime_r(&base, &tm);
  request.base_time =
      DateTime{static_cast<uint16_t>(tm.tm_year + 1900), static_cast<uint8_t>(tm.tm_mon + 1),
               static_cast<uint8_t>(tm.tm_mday),         static_cast<uint8_t>(tm.tm_hour),
               static_cast<uint8_t>(tm.tm_min),          static_cast<uint8_t>(tm.tm_sec)};
  request.count = static_cast<uint8_t>(req.time_offsets_us.size());
  for (size_t i = 0; i < req.time_offsets_us.size(); ++i) {
    request.points[i].time_offset_us = req.time_offsets_us[i];
    request.points[i].event.event_index = static_cast<uint16_t>(i);
  }
  const Result<GetPositionAck> ack = session_->request(request);
  if (!ack) {
    res.message = ack.error();
    return true;
  }
  if (ack->code != AckCode::kOk) {
    res.message = "the adapter answered " + ack_code_text(static_cast<uint8_t>(ack->code));
    return true;
  }
  for (size_t i = 0; i < ack->count && i < ack->points.size(); ++i) {
    const TargetPosition& p = ack->points[i];
    sensor_msgs::NavSatFix fix = fix_message(req.base_time + ros::Duration(p.time_offset_us * 1e-6),
                                             config_.world_frame, p.latitude_deg, p.longitude_deg,
                                             p.height_m, sensor_msgs::NavSatStatus::STATUS_FIX);
    res.positions.push_back(fix);
    res.solutions.push_back(static_cast<uint8_t>(p.solution));
  }
  res.success = true;
  res.message = "ok";
  return true;
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
  const transport::LinkState link = session_->link_state();
  if (link != transport::LinkState::kConnected) {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR,
                   std::string("link ") + transport::to_string(link));
  } else if (silent_s < 0 || silent_s > config_.silence_timeout_s) {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "the SKYPORT adapter is silent");
  } else if (b.identity_requests == 0) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "no identity verification yet");
  } else if (b.identity_refused > 0 && b.identity_refused == b.identity_requests) {
    status.summary(diagnostic_msgs::DiagnosticStatus::ERROR, "identity verification refused");
  } else if (b.power_off_announced) {
    status.summary(diagnostic_msgs::DiagnosticStatus::WARN, "the aircraft announces power-off");
  } else {
    status.summary(diagnostic_msgs::DiagnosticStatus::OK, "pushes arriving, identity answered");
  }
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
}

}  // namespace k40t::driver::skyport
