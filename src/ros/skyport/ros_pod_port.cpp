#include "k40t_driver/ros/skyport/ros_pod_port.h"

#include <dynamic_reconfigure/Reconfigure.h>
#include <geometry_msgs/Twist.h>
#include <ros/service.h>
#include <std_srvs/Trigger.h>

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

namespace {
// record/status comes at 1 Hz while recording; older than this, the pod has stopped.
constexpr double kRecordStatusFresh_s = 2.5;

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}
}  // namespace

RosPodPort::RosPodPort(ros::NodeHandle nh, std::string reconfigure, double service_timeout_s,
                       Events events)
    : nh_(nh),
      reconfigure_(std::move(reconfigure)),
      timeout_(service_timeout_s),
      events_(std::move(events)) {
  cmd_rate_ = nh_.advertise<geometry_msgs::Twist>("gimbal/cmd_rate", 1);
  joints_ = nh_.subscribe("joint_states", 1, &RosPodPort::on_joints, this);
  camera_ = nh_.subscribe("camera/status", 1, &RosPodPort::on_camera, this);
  visible_ = nh_.subscribe("visible/status", 1, &RosPodPort::on_visible, this);
  record_ = nh_.subscribe("record/status", 1, &RosPodPort::on_record, this);
  photo_ = nh_.subscribe("photo/status", 10, &RosPodPort::on_photo, this);
}

template <class Srv>
PodCall RosPodPort::call(const std::string& name, Srv& srv) {
  ros::ServiceClient client = nh_.serviceClient<Srv>(name);
  if (!client.waitForExistence(timeout_))
    return {false, "the driver's service " + client.getService() + " is not there"};
  if (!client.call(srv)) return {false, "call of " + client.getService() + " failed"};
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
  ros::ServiceClient client = nh_.serviceClient<dynamic_reconfigure::Reconfigure>(reconfigure_);
  if (!client.waitForExistence(timeout_))
    return {false, "the driver's " + client.getService() + " is not there"};
  if (!client.call(srv)) return {false, "call of " + client.getService() + " failed"};
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
  if (result.ok) {
    std::lock_guard<std::mutex> lock(mutex_);
    recording_commanded_ = start;
    if (!start) state_.recording = false;
  }
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
  return reconfigure_int("camera_mode", video);
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
  std::lock_guard<std::mutex> lock(mutex_);
  PodSnapshot out = state_;
  const bool fresh = !record_status_at_.isZero() &&
                     (ros::Time::now() - record_status_at_).toSec() < kRecordStatusFresh_s;
  out.recording = recording_commanded_ || (fresh && state_.recording);
  return out;
}

void RosPodPort::on_joints(const sensor_msgs::JointState::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  for (size_t i = 0; i < msg->name.size() && i < msg->position.size(); ++i) {
    const double velocity = i < msg->velocity.size() ? msg->velocity[i] : 0.0;
    if (ends_with(msg->name[i], "yaw_joint")) {
      state_.yaw_rad = msg->position[i];
      state_.yaw_rate_rad_s = velocity;
    } else if (ends_with(msg->name[i], "roll_joint")) {
      state_.roll_rad = msg->position[i];
      state_.roll_rate_rad_s = velocity;
    } else if (ends_with(msg->name[i], "pitch_joint")) {
      state_.pitch_rad = msg->position[i];
      state_.pitch_rate_rad_s = velocity;
    }
  }
  state_.have_joints = true;
}

void RosPodPort::on_camera(const k40t_driver::CameraStatus::ConstPtr& msg) {
  bool became_full = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    became_full = msg->sd_state == k40t_driver::CameraStatus::SD_FULL &&
                  (!state_.have_camera || state_.sd_state != msg->sd_state);
    state_.have_camera = true;
    state_.video_mode = msg->mode == k40t_driver::CameraStatus::MODE_VIDEO;
    state_.photo_mode = msg->photo_mode;
    state_.burst_count = msg->burst_count;
    state_.timelapse_interval_s = msg->timelapse_interval_s;
    state_.sd_state = msg->sd_state;
    state_.image_mode = msg->image_mode;
    state_.sd_total_mb = msg->sd_total_mb;
    state_.sd_free_mb = msg->sd_free_mb;
  }
  if (became_full && events_) events_("K40T: SD card full");
}

void RosPodPort::on_visible(const k40t_driver::VisibleStatus::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  state_.have_visible = true;
  state_.zoom_ratio = msg->zoom_ratio;
  state_.focal_length_mm = msg->focal_length_mm;
}

void RosPodPort::on_photo(const k40t_driver::PhotoStatus::ConstPtr& msg) {
  std::lock_guard<std::mutex> lock(mutex_);
  ++state_.photo_status_count;
  state_.photo_state = msg->state;
}

void RosPodPort::on_record(const k40t_driver::RecordStatus::ConstPtr& msg) {
  using k40t_driver::RecordStatus;
  const bool recording = msg->state == RecordStatus::STATE_RECORDING ||
                         msg->state == RecordStatus::STATE_TIMELAPSE_RECORDING;
  bool started = false, stopped = false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const bool was = state_.recording;
    started = recording && !was;
    stopped = !recording && was;
    state_.recording = recording;
    state_.record_duration_s = msg->duration_s;
    record_status_at_ = ros::Time::now();
    if (!recording) recording_commanded_ = false;
  }
  if (started && events_) events_("K40T: recording started");
  if (stopped && events_) events_("K40T: recording stopped (" + msg->state_text + ")");
}

}  // namespace k40t::driver::skyport
