// Every topic the live driver publishes from what the pod sends: the decoded topics
// (decoded_topics.h, through ros::Publisher), the static sensor frames on TF, and the raw frames.
// Registers its handlers on the PodDriver in the constructor (before PodDriver::start()); they
// run on the link's I/O thread and only convert and publish. Stamps are the frames' (PodDriver),
// so a replay publishes the same messages as the live run did.
#pragma once

#include <functional>
#include <memory>
#include <string>

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <tf2_ros/static_transform_broadcaster.h>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/ros/ros_params.h"

namespace k40t::driver {

// The live sink of advertise_decoded_topics(): one ros::Publisher per topic, in `nh`'s namespace.
class RosTopicSink {
 public:
  explicit RosTopicSink(ros::NodeHandle nh) : nh_(nh) {}
  template <class RosMsg>
  std::function<void(const RosMsg&)> advertise(const std::string& topic, uint32_t queue,
                                               bool latch) {
    ros::Publisher publisher = nh_.advertise<RosMsg>(topic, queue, latch);
    return [publisher](const RosMsg& message) { publisher.publish(message); };
  }

 private:
  ros::NodeHandle nh_;
};

class TopicPublisher {
 public:
  TopicPublisher(ros::NodeHandle nh, PodDriver& driver, const RosPodConfig& config);

 private:
  ros::Publisher raw_rx_, raw_tx_;
  std::unique_ptr<tf2_ros::StaticTransformBroadcaster> static_tf_;
};

}  // namespace k40t::driver
