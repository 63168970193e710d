#include "k40t_driver/ros/topic_publisher.h"

#include "k40t_driver/ros/decoded_topics.h"

namespace k40t::driver {

TopicPublisher::TopicPublisher(ros::NodeHandle nh, PodDriver& driver, const RosPodConfig& config) {
  // The publishers live in the driver's handlers (copies of ros::Publisher share one
  // advertisement), as long as the driver.
  RosTopicSink sink(nh);
  advertise_decoded_topics(sink, driver, config);

  // Raw frames. In replay mode raw/rx is the input (replay_input.h), not an output.
  if (!driver.replay()) {
    raw_rx_ = nh.advertise<k40t_driver::Frame>("raw/rx", 100);
    raw_tx_ = nh.advertise<k40t_driver::Frame>("raw/tx", 100);
    driver.on_rx_frame([this](const protocol::FrameView& f, StampNs s) {
      raw_rx_.publish(to_frame_msg(f.bytes, f.size, to_ros_time(s), k40t_driver::Frame::RX));
    });
    driver.on_tx_frame([this](const protocol::FrameView& f, StampNs s) {
      raw_tx_.publish(to_frame_msg(f.bytes, f.size, to_ros_time(s), k40t_driver::Frame::TX));
    });
  }

  if (config.publish_tf) {
    static_tf_ = std::make_unique<tf2_ros::StaticTransformBroadcaster>();
    static_tf_->sendTransform(sensor_transforms(ros::Time::now(), config.ids, config.geometry));
  }
}

}  // namespace k40t::driver
