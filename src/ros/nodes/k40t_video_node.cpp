// k40t_video_node: the video streamer as a standalone node (the nodelet k40t_driver/VideoNodelet
// is the same thing inside a nodelet manager).
#include "k40t_driver/ros/component_host.h"
#include "k40t_driver/ros/video/video_streamer.h"

int main(int argc, char** argv) {
  return k40t::driver::run_standalone_node<k40t::driver::VideoStreamer>(
      argc, argv, "video", "K40T video", k40t::driver::Callbacks::kOneAtATime);
}
