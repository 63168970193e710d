// Replay mode's input: the raw/rx topic (k40t_driver/Frame, e.g. from `rosbag play`) fed frame by
// frame into the PodDriver with each frame's recorded stamp, so every decoded topic is published
// again exactly as it was recorded.
#pragma once

#include <ros/node_handle.h>
#include <ros/subscriber.h>

#include "k40t_driver/Frame.h"
#include "k40t_driver/driver/pod_driver.h"

namespace k40t::driver {

class ReplayInput {
 public:
  ReplayInput(ros::NodeHandle nh, PodDriver& driver);

 private:
  void on_frame(const k40t_driver::Frame::ConstPtr& frame);

  PodDriver& driver_;
  ros::Subscriber subscriber_;
};

}  // namespace k40t::driver
