// The SKYPORT bridge's ROS glue: the payload-side PSDK session on the SKYPORT UART, the
// SkyportBridge (commands answered by driving the pod), every data push as ROS messages under
// skyport/, the pod fed from them (fix, attitude, time_reference, when feed_pod), floating-window
// messages for pod events, transparent data to and from topics, positioning as a service, and
// diagnostics. Run by SkyportNodelet and k40t_skyport_node. See docs/skyport.md.
#pragma once

#include <atomic>
#include <chrono>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/service_server.h>
#include <ros/subscriber.h>
#include <ros/timer.h>
#include <std_msgs/UInt8MultiArray.h>

#include "k40t_driver/GetPosition.h"
#include "k40t_driver/protocol/result.h"
#include "k40t_driver/psdk/session.h"
#include "k40t_driver/ros/skyport/ros_pod_port.h"
#include "k40t_driver/ros/skyport/skyport_config.h"
#include "k40t_driver/skyport/position_query.h"
#include "k40t_driver/skyport/pps_rule.h"
#include "k40t_driver/skyport/skyport_bridge.h"

namespace k40t::driver::skyport {

class SkyportRos {
 public:
  static Result<std::unique_ptr<SkyportRos>> create(ros::NodeHandle nh, ros::NodeHandle private_nh);
  ~SkyportRos();

 private:
  SkyportRos(ros::NodeHandle nh, ros::NodeHandle private_nh, SkyportConfig config,
             std::unique_ptr<psdk::Session> session);
  void advertise();
  void register_pushes();
  // A push published on `topic`, into `publisher`, as `convert(push, now)` gives it.
  template <class Push, class Convert>
  void forward(ros::Publisher& publisher, const std::string& topic, Convert convert);
  void register_transparent();
  // ~handled_commands: the dispatch table's keys ("0x03/0x0A"), for the golden-frame coverage
  // check of the rostest (test_skyport.py).
  void publish_handled_commands();
  void on_to_mobile(const std_msgs::UInt8MultiArray::ConstPtr& msg);
  void on_to_onboard(const std_msgs::UInt8MultiArray::ConstPtr& msg);
  bool on_get_position(k40t_driver::GetPosition::Request& req,
                       k40t_driver::GetPosition::Response& res);
  void diagnose(diagnostic_updater::DiagnosticStatusWrapper& status);

  ros::NodeHandle nh_, private_nh_;
  SkyportConfig config_;
  std::unique_ptr<psdk::Session> session_;
  PositionQuery positions_;  // skyport/get_position; told of every UTC push used
  std::unique_ptr<RosPodPort> pod_;
  std::unique_ptr<SkyportBridge> bridge_;
  std::atomic<SkyportBridge*> bridge_ptr_{nullptr};

  ros::Publisher attitude_, imu_, gps_, relative_height_, raw_gps_, raw_gps_velocity_, rtk_,
      rtk_velocity_, battery_, power_off_, uav_state_, link_, baro_, app_time_, utc_time_,
      other_payload_, from_mobile_, from_onboard_;
  ros::Publisher feed_fix_, feed_attitude_, feed_time_;
  ros::Subscriber to_mobile_, to_onboard_;
  ros::ServiceServer get_position_;
  diagnostic_updater::Updater diagnostics_;
  ros::Timer diagnostic_timer_;

  std::mutex mutex_;
  std::optional<std::chrono::steady_clock::time_point> last_frame_;
  std::optional<bool> power_off_soon_;
  uint8_t other_payload_type_ = 0;
  float other_payload_focal_mm_ = std::nanf("");
  std::atomic<uint64_t> utc_pushes_invalid_{0};
  std::atomic<uint64_t> utc_pushes_late_{0};  // 3.3.10's 500 ms rule (with or without PPS)
  // No pps_topic: used after the rule relative to the most punctual push (pps_rule.h).
  std::atomic<uint64_t> utc_pushes_unchecked_{0};
  UtcPushLateness utc_lateness_;            // session I/O thread only
  std::optional<ros::Time> last_pps_edge_;  // local time of the newest PPS rising edge
  ros::Subscriber pps_;
};

}  // namespace k40t::driver::skyport
