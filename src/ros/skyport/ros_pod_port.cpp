#include "k40t_driver/ros/skyport/ros_pod_port.h"

#include <dynamic_reconfigure/Reconfigure.h>
#include <geometry_msgs/Twist.h>
#include <ros/service.h>
#include <std_srvs/Trigger.h>
#include <tf2/LinearMath/Matrix3x3.h>
#include <tf2/LinearMath/Quaternion.h>

#include "k40t_driver/Calibrate.h"
#include "k40t_driver/Focus.h"
#include "k40t_driver/MeasureRange.h"
#include "k40t_driver/Record.h"
#include "k40t_driver/SetAngle.h"
#include "k40t_driver/SetPhotoMode.h"
#include "k40t_driver/SetZoom.h"
#include "k40t_driver/TakePhoto.h"
#include "k40t_driver/Zoom.h"
#include "k40t_driver/protocol/response_code.h"

namespace k40t::driver::skyport {

static_assert(k40t_driver::CameraStatus::SD_FULL == kSdFull, "pod_state_tracker.h's kSdFull");

namespace {
double ros_now_s() {
  return ros::Time::now().toSec();
}
}  // namespace

RosPodPort::RosPodPort(ros::NodeHandle nh, std::string reconfigure, double service_timeout_s,
                       Events events)
    : nh_(nh),
      reconfigure_(std::move(reconfigure)),
      timeout_(service_timeout_s),
      tracker_(std::move(events)) {
  cmd_rate_ = nh_.advertise<geometry_msgs::Twist>("gimbal/cmd_rate", 1);
  attitude_ = nh_.subscribe("gimbal/attitude", 1, &RosPodPort::on_attitude, this);
  camera_ = nh_.subscribe("camera/status", 1, &RosPodPort::on_camera, this);
  record_ = nh_.subscribe("record/status", 1, &RosPodPort::on_record, this);
  // The reports passed on as they are.
  joints_ = nh_.subscribe<sensor_msgs::JointState>(
      "joint_states", 1, [this](const sensor_msgs::JointState::ConstPtr& msg) {
        tracker_.joints(msg->name, msg->position, msg->velocity, ros_now_s());
      });
  visible_ = nh_.subscribe<k40t_driver::VisibleStatus>(
      "visible/status", 1, [this](const k40t_driver::VisibleStatus::ConstPtr& msg) {
        tracker_.visible(msg->zoom_ratio, msg->focal_length_mm, ros_now_s());
      });
  photo_ = nh_.subscribe<k40t_driver::PhotoStatus>(
      "photo/status", 10,
      [this](const k40t_driver::PhotoStatus::ConstPtr& msg) { tracker_.photo(msg->state); });
  upgrade_ = nh_.subscribe<k40t_driver::CameraUpgradeStatus>(
      "camera/upgrade_status", 10, [this](const k40t_driver::CameraUpgradeStatus::ConstPtr& msg) {
        tracker_.repair(msg->state, msg->progress_percent);
      });
}

template <class Srv>
bool RosPodPort::client(const std::string& name, ros::ServiceClient& out, std::string& why) {
  {
    std::lock_guard<std::mutex> lock(clients_mutex_);
    const auto it = clients_.find(name);
    if (it != clients_.end() && it->second.isValid()) {
      out = it->second;
      return true;
    }
  }
  ros::ServiceClient made = nh_.serviceClient<Srv>(name, /*persistent=*/true);
  if (!made.waitForExistence(timeout_)) {
    why = "the driver's service " + made.getService() + " is not there";
    return false;
  }
  std::lock_guard<std::mutex> lock(clients_mutex_);
  clients_[name] = made;
  out = made;
  return true;
}

template <class Srv>
PodCall RosPodPort::call(const std::string& name, Srv& srv) {
  ros::ServiceClient c;
  std::string why;
  if (!client<Srv>(name, c, why)) return {false, why};
  if (!c.call(srv)) {
    std::lock_guard<std::mutex> lock(clients_mutex_);
    clients_.erase(name);  // the connection broke (driver restarted?): a new one next time
    return {false, "call of " + c.getService() + " failed"};
  }
  PodCall result{static_cast<bool>(srv.response.success), srv.response.message};
  // The driver's refusal message carries the pod's response text ("... refused by the pod:
  // taking photo (response code 0x0203)").
  const std::string busy = protocol::response_text(protocol::ResponseCode::kPhotoInProgress);
  result.photo_in_progress = !result.ok && result.message.find(busy) != std::string::npos;
  return result;
}

PodCall RosPodPort::reconfigure_int(const std::string& name, int value) {
  dynamic_reconfigure::Reconfigure srv;
  dynamic_reconfigure::IntParameter p;
  p.name = name;
  p.value = value;
  srv.request.config.ints.push_back(p);
  ros::ServiceClient c;
  std::string why;
  if (!client<dynamic_reconfigure::Reconfigure>(reconfigure_, c, why)) return {false, why};
  if (!c.call(srv)) {
    std::lock_guard<std::mutex> lock(clients_mutex_);
    clients_.erase(reconfigure_);
    return {false, "call of " + c.getService() + " failed"};
  }
  for (const auto& applied : srv.response.config.ints) {
    if (applied.name == name)
      return {applied.value == value, applied.value == value ? "ok" : name + " not applied"};
  }
  return {false, name + " not in the driver's answer"};
}

PodCall RosPodPort::take_photo(bool stop) {
  k40t_driver::TakePhoto srv;
  srv.request.lens = k40t_driver::TakePhoto::Request::LENS_DEFAULT;
  srv.request.stop = stop;
  return call("take_photo", srv);
}

PodCall RosPodPort::record(bool start) {
  k40t_driver::Record srv;
  srv.request.start = start;
  srv.request.lens = k40t_driver::Record::Request::LENS_DEFAULT;
  PodCall result = call("record", srv);
  if (result.ok) tracker_.record_accepted(start, ros_now_s());
  return result;
}

PodCall RosPodPort::set_photo_mode(uint8_t mode, uint8_t interval_s, uint8_t burst_count) {
  k40t_driver::SetPhotoMode srv;
  srv.request.mode = mode;
  srv.request.timelapse_interval_s = interval_s;
  srv.request.burst_count = burst_count;
  return call("set_photo_mode", srv);
}

PodCall RosPodPort::set_video_mode(bool video) {
  PodCall call = reconfigure_int("camera_mode", video);
  if (call.ok) tracker_.video_mode_accepted(video);
  return call;
}

PodCall RosPodPort::set_metering(int metering) {
  return reconfigure_int("metering", metering);
}

PodCall RosPodPort::set_zoom(double ratio) {
  k40t_driver::SetZoom srv;
  srv.request.ratio = static_cast<float>(ratio);
  return call("set_zoom", srv);
}

PodCall RosPodPort::zoom(PodZoom action) {
  k40t_driver::Zoom srv;
  srv.request.action = static_cast<uint8_t>(action);
  return call("zoom", srv);
}

PodCall RosPodPort::focus(PodFocus mode, uint16_t x1, uint16_t y1, uint16_t x2, uint16_t y2) {
  k40t_driver::Focus srv;
  srv.request.mode = static_cast<uint8_t>(mode);
  srv.request.x1 = x1;
  srv.request.y1 = y1;
  srv.request.x2 = x2;
  srv.request.y2 = y2;
  return call("focus", srv);
}

PodCall RosPodPort::format_sd() {
  std_srvs::Trigger srv;
  return call("format_sd", srv);
}

PodCall RosPodPort::set_angle(double pitch_rad, double yaw_rad) {
  k40t_driver::SetAngle srv;
  srv.request.pitch = pitch_rad;
  srv.request.yaw = yaw_rad;
  return call("gimbal/set_angle", srv);
}

PodCall RosPodPort::set_rate(double pitch_rad_s, double yaw_rad_s) {
  geometry_msgs::Twist twist;
  twist.angular.y = pitch_rad_s;
  twist.angular.z = yaw_rad_s;
  cmd_rate_.publish(twist);
  return {true, "ok"};
}

PodCall RosPodPort::center() {
  std_srvs::Trigger srv;
  return call("gimbal/center", srv);
}

PodCall RosPodPort::calibrate() {
  k40t_driver::Calibrate srv;
  srv.request.kind = k40t_driver::Calibrate::Request::DRIFT;
  return call("gimbal/calibrate", srv);
}

PodCall RosPodPort::set_palette(int palette) {
  return reconfigure_int("palette", palette);
}

PodCall RosPodPort::set_image_mode(int image_mode) {
  return reconfigure_int("image_mode", image_mode);
}

PodCall RosPodPort::measure_range(double& range_m) {
  k40t_driver::MeasureRange srv;
  PodCall result = call("laser/measure", srv);
  range_m = srv.response.range;
  return result;
}

PodSnapshot RosPodPort::snapshot() const {
  return tracker_.snapshot(ros_now_s());
}

void RosPodPort::on_attitude(const geometry_msgs::QuaternionStamped::ConstPtr& msg) {
  // The driver builds it as Rz(yaw) Ry(pitch) Rx(roll) of the pod's attitude angles (REP 103).
  double roll = 0, pitch = 0, yaw = 0;
  const auto& q = msg->quaternion;
  tf2::Matrix3x3(tf2::Quaternion(q.x, q.y, q.z, q.w).normalized()).getRPY(roll, pitch, yaw);
  tracker_.attitude(roll, pitch, yaw);
}

void RosPodPort::on_camera(const k40t_driver::CameraStatus::ConstPtr& msg) {
  CameraReport report;
  report.video_mode = msg->mode == k40t_driver::CameraStatus::MODE_VIDEO;
  report.photo_mode = msg->photo_mode;
  report.burst_count = msg->burst_count;
  report.timelapse_interval_s = msg->timelapse_interval_s;
  report.sd_state = msg->sd_state;
  report.image_mode = msg->image_mode;
  report.sd_total_mb = msg->sd_total_mb;
  report.sd_free_mb = msg->sd_free_mb;
  tracker_.camera(report, ros_now_s());
}

void RosPodPort::on_record(const k40t_driver::RecordStatus::ConstPtr& msg) {
  using k40t_driver::RecordStatus;
  const bool recording = msg->state == RecordStatus::STATE_RECORDING ||
                         msg->state == RecordStatus::STATE_TIMELAPSE_RECORDING;
  tracker_.record(recording, msg->duration_s, msg->state_text, ros_now_s());
}

}  // namespace k40t::driver::skyport
