// gimbal/look_at (actionlib, action/LookAt.action) and gimbal/look_at_point
// (geometry_msgs/PointStamped, latest wins, stops following when no point came for
// ~look_at_point_timeout), and the marker topic gimbal/look_at_marker
// (visualization_msgs/MarkerArray: the target, the line of sight, the boresight). One thread runs
// the control step at ~look_at_rate (20 Hz) while something is followed and sleeps otherwise:
// the target in the gimbal's base frame (look_at_target.h), the ROS-free step
// (driver/look_at_controller.h), then 0x000012 (or rates, ~look_at_drive), the zoom policy and
// the feedback. A goal has the gimbal to itself: look_at_point is ignored while one runs.
// docs/ros_interface.md "Looking at a place".
//
// Lifetime: construct before PodDriver::start() (its handlers), start() after, shutdown() before
// PodDriver::stop() (the thread sends through the driver).
#pragma once

#include <atomic>
#include <cmath>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>

#include <actionlib/server/simple_action_server.h>
#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <ros/subscriber.h>
#include <sensor_msgs/CameraInfo.h>

#include "k40t_driver/LookAtAction.h"
#include "k40t_driver/driver/look_at_controller.h"
#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/ros/look_at_target.h"
#include "k40t_driver/ros/ros_params.h"

namespace k40t::driver {

class LookAtServer {
 public:
  LookAtServer(ros::NodeHandle nh, const ros::NodeHandle& private_nh, PodDriver& driver,
               const RosPodConfig& config, const tf2_ros::Buffer& tf);
  ~LookAtServer();
  LookAtServer(const LookAtServer&) = delete;
  LookAtServer& operator=(const LookAtServer&) = delete;

  void start();
  void shutdown();  // idempotent: ends a running goal, stops the gimbal, joins the thread

  // What is followed now (a goal's target or the latest look_at_point), and the controller.
  struct Following {
    explicit Following(const LookAtConfig& config) : controller(config) {}
    LookAtTarget target;
    bool from_goal = false;
    bool follow = true;
    double tolerance_deg = 0;
    ros::Time start, deadline;  // deadline: settle-once goals only
    LookAtController controller;
    uint8_t zoom_policy = k40t_driver::LookAtGoal::ZOOM_LEAVE;
    double zoom_ratio = 1;
    std::optional<FootprintZoom> footprint;
    int settled = 0;  // consecutive steps within the tolerance
    double last_error_deg = std::nan("");
    double last_slant_m = std::nan("");
  };

 private:
  // A goal's checks (nothing is sent for a refused goal): its reason, or none.
  std::optional<std::string> configure(Following& f, const k40t_driver::LookAtGoal& goal) const;

  void on_goal();
  void on_preempt();
  void on_point(const geometry_msgs::PointStamped::ConstPtr& msg);
  void run();
  // Starts what the callbacks asked for, ends what must end; the session to step, if any.
  Following* update_session(const ros::Time& now);
  // One control step; false when following must end (the result is then set).
  bool step(Following& f, const ros::Time& now);
  void begin(Following& f);
  void end(Following& f, bool success, const std::string& message, bool preempted = false);
  void stop_gimbal();
  void apply_zoom(Following& f, double slant_m);
  void publish_feedback(Following& f, const LookAtStep& step, double slant_m,
                        const geo::Vector3& target, const ros::Time& now);

  PodDriver& driver_;
  TargetResolver resolver_;
  LookAtConfig config_;
  double period_s_ = 0.05;
  double point_timeout_s_ = 1.0;
  double tan_half_fov_1x_ = 0;  // the tele's, for the footprint zoom

  ros::Subscriber point_sub_, camera_info_sub_;
  ros::Publisher marker_pub_;

  std::mutex mutex_;  // guards everything below it up to the server
  std::condition_variable wakeup_;
  bool stopping_ = false;
  k40t_driver::LookAtGoalConstPtr pending_goal_;
  bool preempt_ = false;
  std::optional<geometry_msgs::PointStamped> latest_point_;
  ros::Time latest_point_time_;
  std::optional<geo::GimbalAim> joints_;
  double joints_s_ = 0;
  double zoom_ = std::nan("");
  std::optional<sensor_msgs::CameraInfo> camera_info_;

  std::unique_ptr<Following> session_;  // the control thread's only
  std::atomic<bool> angle_in_flight_{false};
  std::atomic<bool> shut_down_{false};
  actionlib::SimpleActionServer<k40t_driver::LookAtAction> server_;
  std::thread thread_;
};

}  // namespace k40t::driver
