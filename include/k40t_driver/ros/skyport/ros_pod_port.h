// The PodPort of the SKYPORT bridge over the driver's ROS interface: its services (take_photo,
// record, set_zoom, zoom, focus, set_photo_mode, format_sd, gimbal/set_angle, gimbal/center,
// gimbal/calibrate), dynamic_reconfigure (camera_mode, metering), the gimbal/cmd_rate topic, and
// its status topics (joint_states, gimbal/attitude, camera/status, visible/status, record/status,
// photo/status, camera/upgrade_status) for the pod's state. Service clients are persistent and
// cached per service (a new client per call costs a connection and a lookup each time); a client
// whose call failed is dropped and made again on the next call. The state and its rules are the
// ROS-free PodStateTracker's; `events` hears of pod events worth a floating-window message
// (recording started or stopped, SD card full).
#pragma once

#include <functional>
#include <map>
#include <mutex>
#include <string>

#include <geometry_msgs/QuaternionStamped.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/subscriber.h>
#include <sensor_msgs/JointState.h>

#include "k40t_driver/CameraStatus.h"
#include "k40t_driver/CameraUpgradeStatus.h"
#include "k40t_driver/PhotoStatus.h"
#include "k40t_driver/RecordStatus.h"
#include "k40t_driver/VisibleStatus.h"
#include "k40t_driver/skyport/pod_port.h"
#include "k40t_driver/skyport/pod_state_tracker.h"

namespace k40t::driver::skyport {

class RosPodPort : public PodPort {
 public:
  using Events = std::function<void(const std::string& text)>;
  // `nh`: the driver's namespace; `reconfigure`: its dynamic_reconfigure service, relative to it.
  RosPodPort(ros::NodeHandle nh, std::string reconfigure, double service_timeout_s, Events events);

  PodCall take_photo(bool stop) override;
  PodCall record(bool start) override;
  PodCall set_photo_mode(uint8_t mode, uint8_t interval_s, uint8_t burst_count) override;
  PodCall set_video_mode(bool video) override;
  PodCall set_metering(int metering) override;
  PodCall set_zoom(double ratio) override;
  PodCall zoom(PodZoom action) override;
  PodCall focus(PodFocus mode, uint16_t x1, uint16_t y1, uint16_t x2, uint16_t y2) override;
  PodCall format_sd() override;
  PodCall set_angle(double pitch_rad, double yaw_rad) override;
  PodCall set_rate(double pitch_rad_s, double yaw_rad_s) override;
  PodCall center() override;
  PodCall calibrate() override;
  PodCall set_palette(int palette) override;
  PodCall set_image_mode(int image_mode) override;
  PodCall measure_range(double& range_m) override;
  PodSnapshot snapshot() const override;

 private:
  template <class Srv>
  PodCall call(const std::string& name, Srv& srv);
  // The cached persistent client of `name` (absolute), made when missing or broken; false with
  // `why` when the service is not there within the timeout.
  template <class Srv>
  bool client(const std::string& name, ros::ServiceClient& out, std::string& why);
  PodCall reconfigure_int(const std::string& name, int value);
  void on_attitude(const geometry_msgs::QuaternionStamped::ConstPtr& msg);
  void on_camera(const k40t_driver::CameraStatus::ConstPtr& msg);
  void on_record(const k40t_driver::RecordStatus::ConstPtr& msg);

  ros::NodeHandle nh_;
  std::string reconfigure_;
  ros::Duration timeout_;
  PodStateTracker tracker_;  // before the subscriptions that feed it: it outlives them
  ros::Publisher cmd_rate_;
  ros::Subscriber joints_, attitude_, camera_, visible_, record_, photo_, upgrade_;

  std::mutex clients_mutex_;
  std::map<std::string, ros::ServiceClient> clients_;
};

}  // namespace k40t::driver::skyport
