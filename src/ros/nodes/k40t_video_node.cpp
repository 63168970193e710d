// k40t_video_node: the video streamer as a standalone node (the nodelet k40t_driver/VideoNodelet
// is the same thing inside a nodelet manager).
#include <ros/ros.h>

#include "k40t_driver/ros/stop_signals.h"
#include "k40t_driver/ros/video/video_streamer.h"

int main(int argc, char** argv) {
  ros::init(argc, argv, "video");
  k40t::driver::shutdown_on_sigterm();
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  if (k40t::driver::stop_requested_before_ros_start()) return 0;  // Ctrl-C while loading
  auto streamer = k40t::driver::VideoStreamer::create(nh, private_nh);
  if (!streamer) {
    ROS_FATAL("K40T video not started: %s", streamer.error().c_str());
    return 1;
  }
  ros::spin();
  return 0;
}
