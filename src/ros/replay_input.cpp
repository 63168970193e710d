#include "k40t_driver/ros/replay_input.h"

namespace k40t::driver {

ros::Subscriber subscribe_replay_input(ros::NodeHandle nh, PodDriver& driver) {
  // A deep queue: rosbag play does not wait for us, and a dropped frame is a missing message.
  return nh.subscribe<k40t_driver::Frame>(
      "raw/rx", 10000,
      [&driver](const k40t_driver::Frame::ConstPtr& frame) {
        if (frame->direction != k40t_driver::Frame::RX) return;
        driver.replay_frame(frame->data.data(), frame->data.size(),
                            static_cast<StampNs>(frame->stamp.toNSec()));
      },
      ros::VoidConstPtr(), ros::TransportHints().tcpNoDelay());
}

}  // namespace k40t::driver
