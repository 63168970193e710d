#include "k40t_driver/ros/replay_input.h"

namespace k40t::driver {

ReplayInput::ReplayInput(ros::NodeHandle nh, PodDriver& driver) : driver_(driver) {
  // A deep queue: rosbag play does not wait for us, and a dropped frame is a missing message.
  subscriber_ = nh.subscribe("raw/rx", 10000, &ReplayInput::on_frame, this,
                             ros::TransportHints().tcpNoDelay());
}

void ReplayInput::on_frame(const k40t_driver::Frame::ConstPtr& frame) {
  if (frame->direction != k40t_driver::Frame::RX) return;
  driver_.replay_frame(frame->data.data(), frame->data.size(),
                       static_cast<StampNs>(frame->stamp.toNSec()));
}

}  // namespace k40t::driver
