// k40t_driver/VideoNodelet: the pod's video in the same nodelet manager as PodNodelet, so that
// image subscribers in that manager receive the published shared pointers without a copy.
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "k40t_driver/ros/video/video_streamer.h"

namespace k40t::driver {

class VideoNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    Result<std::unique_ptr<VideoStreamer>> streamer =
        VideoStreamer::create(getNodeHandle(), getPrivateNodeHandle());
    if (!streamer) {
      NODELET_FATAL("K40T video not started: %s", streamer.error().c_str());
      return;
    }
    streamer_ = std::move(streamer.value());
  }

  std::unique_ptr<VideoStreamer> streamer_;
};

}  // namespace k40t::driver

PLUGINLIB_EXPORT_CLASS(k40t::driver::VideoNodelet, nodelet::Nodelet)
