// k40t_skyport_node: the SKYPORT bridge as a standalone node (the same SkyportRos as the nodelet).
#include <ros/ros.h>

#include "k40t_driver/ros/skyport/skyport_ros.h"
#include "k40t_driver/ros/stop_signals.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "k40t_skyport");
  k40t::driver::shutdown_on_sigterm();
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  if (k40t::driver::stop_requested_before_ros_start()) return 0;  // Ctrl-C while loading
  auto bridge = k40t::driver::skyport::SkyportRos::create(nh, private_nh);
  if (!bridge) {
    ROS_FATAL("SKYPORT bridge not started: %s", bridge.error().c_str());
    return 1;
  }
  // Pushes keep being published while a command waits for the pod's service.
  ros::AsyncSpinner spinner(4);
  spinner.start();
  ros::waitForShutdown();
  return 0;
}
