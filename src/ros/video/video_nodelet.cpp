// k40t_driver/VideoNodelet: the pod's video in the same nodelet manager as PodNodelet, so that
// image subscribers in that manager receive the published shared pointers without a copy.
#include "k40t_driver/ros/component_host.h"
#include "k40t_driver/ros/video/video_streamer.h"

K40T_COMPONENT_NODELET(k40t::driver, VideoNodelet, VideoStreamer, "K40T video", kOneAtATime)
