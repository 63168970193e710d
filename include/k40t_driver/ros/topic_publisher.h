// Every topic the driver publishes from what the pod sends: joint_states and TF from the attitude
// report, the status messages, laser range and target, and the raw frames. Registers its handlers
// on the PodDriver in the constructor (before PodDriver::start()); they run on the link's I/O
// thread and only convert and publish. Stamps are the frames' (PodDriver), so a replay publishes
// the same messages as the live run did.
#pragma once

#include <ros/node_handle.h>
#include <ros/publisher.h>
#include <tf2_ros/static_transform_broadcaster.h>
#include <tf2_ros/transform_broadcaster.h>

#include "k40t_driver/ros/pod_driver.h"
#include "k40t_driver/ros/ros_params.h"

namespace k40t::driver {

class TopicPublisher {
 public:
  TopicPublisher(ros::NodeHandle nh, PodDriver& driver, const RosPodConfig& config);

 private:
  template <class RosMsg>
  ros::Publisher advertise(const std::string& topic, uint32_t queue = 10, bool latch = false) {
    return nh_.advertise<RosMsg>(topic, queue, latch);
  }
  void publish_attitude(const protocol::GimbalAttitude& attitude, StampNs stamp);

  ros::NodeHandle nh_;
  RosPodConfig config_;
  ros::Publisher joint_states_, attitude_, gimbal_status_, camera_status_, visible_status_;
  ros::Publisher thermal_stats_, laser_range_, laser_target_, photo_status_, record_status_;
  ros::Publisher zoom_status_, reshoot_status_, tf_upgrade_status_, sd_format_status_;
  ros::Publisher camera_upgrade_status_;
  ros::Publisher raw_rx_, raw_tx_;
  std::unique_ptr<tf2_ros::TransformBroadcaster> tf_;
  std::unique_ptr<tf2_ros::StaticTransformBroadcaster> static_tf_;
};

}  // namespace k40t::driver
