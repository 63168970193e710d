// Replay mode's input: the raw/rx topic (k40t_driver/Frame, e.g. from `rosbag play`) fed frame by
// frame into the PodDriver with each frame's recorded stamp, so every decoded topic is published
// again exactly as it was recorded.
#pragma once

#include <ros/node_handle.h>
#include <ros/subscriber.h>

#include "k40t_driver/Frame.h"
#include "k40t_driver/driver/pod_driver.h"

namespace k40t::driver {

// The subscription; it holds `driver`, which must outlive it.
ros::Subscriber subscribe_replay_input(ros::NodeHandle nh, PodDriver& driver);

}  // namespace k40t::driver
