// k40t_driver/VideoNodelet: the pod's video in the same nodelet manager as PodNodelet, so that
// image subscribers in that manager receive the published shared pointers without a copy.
#include <pluginlib/class_list_macros.hpp>

#include "k40t_driver/ros/component_host.h"
#include "k40t_driver/ros/video/video_streamer.h"

namespace k40t::driver {

class VideoNodelet : public ComponentNodelet<VideoStreamer> {
 public:
  VideoNodelet() : ComponentNodelet("K40T video", Callbacks::kOneAtATime) {}
};

}  // namespace k40t::driver

PLUGINLIB_EXPORT_CLASS(k40t::driver::VideoNodelet, nodelet::Nodelet)
