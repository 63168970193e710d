// k40t_node: the driver as a standalone node (the same RosPod as the nodelet).
#include <ros/ros.h>

#include "k40t_driver/ros/ros_pod.h"
#include "k40t_driver/ros/stop_signals.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "k40t_driver");
  k40t::driver::shutdown_on_sigterm();
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  if (k40t::driver::stop_requested_before_ros_start()) return 0;  // Ctrl-C while loading
  k40t::Result<std::unique_ptr<k40t::driver::RosPod>> pod =
      k40t::driver::RosPod::create(nh, private_nh);
  if (!pod) {
    ROS_FATAL("K40T driver not started: %s", pod.error().c_str());
    return 1;
  }
  // Services block while they wait for an ACK; the other callbacks keep running meanwhile.
  ros::AsyncSpinner spinner(4);
  spinner.start();
  ros::waitForShutdown();
  return 0;
}
