// The offline sink of advertise_decoded_topics() (decoded_topics.h): each "publish" becomes a
// rosbag::Bag::write, with what a live run's recording would hold:
//   - the topic resolved in the driver's namespace (absolute topics such as /tf as they are);
//   - header.seq as roscpp assigns it: one counter per topic of the publishing node, from 0,
//     counting every publish (roscpp's Publication::incrementSequence);
//   - the header stamp as converted (the frame's recorded stamp);
//   - as the bag's receive time, the receive time of the raw/rx message that carried the frame
//     (set_receive_time() before each frame), so the decoded topics line up with the input bag.
#pragma once

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <string>

#include <ros/message_traits.h>
#include <rosbag/bag.h>

namespace k40t::driver {

class BagTopicSink {
 public:
  // `ns`: the driver's namespace ("/k40t"), where relative topics go.
  BagTopicSink(rosbag::Bag& out, std::string ns) : out_(out), ns_(std::move(ns)) {}

  void set_receive_time(const ros::Time& time) { *receive_time_ = time; }
  // Messages written so far, all topics.
  uint64_t written() const { return *written_; }

  std::string resolve(const std::string& topic) const {
    if (!topic.empty() && topic[0] == '/') return topic;
    return (ns_ == "/" ? "" : ns_) + "/" + topic;
  }

  template <class RosMsg>
  std::function<void(const RosMsg&)> advertise(const std::string& topic, uint32_t /*queue*/,
                                               bool /*latch*/) {
    const std::string resolved = resolve(topic);
    // One counter per topic, like one roscpp Publication per topic and node.
    std::shared_ptr<uint32_t>& seq = seq_[resolved];
    if (!seq) seq = std::make_shared<uint32_t>(0);
    return [&out = out_, resolved, seq, time = receive_time_,
            written = written_](const RosMsg& message) {
      ++*written;
      if constexpr (ros::message_traits::HasHeader<RosMsg>::value) {
        RosMsg numbered = message;
        numbered.header.seq = (*seq)++;
        out.write(resolved, *time, numbered);
      } else {
        ++*seq;
        out.write(resolved, *time, message);
      }
    };
  }

 private:
  rosbag::Bag& out_;
  std::string ns_;
  std::map<std::string, std::shared_ptr<uint32_t>> seq_;
  std::shared_ptr<ros::Time> receive_time_ = std::make_shared<ros::Time>();
  std::shared_ptr<uint64_t> written_ = std::make_shared<uint64_t>(0);
};

}  // namespace k40t::driver
