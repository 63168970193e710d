// The image_transport transport of encoded video (k40t_driver/CompressedVideo): its name (the
// topic is <base>/k40t_video, e.g. image_raw/k40t_video) and its plugins' names as
// k40t_video_plugins.xml declares them.
#pragma once

namespace k40t::driver {

constexpr const char* kVideoTransportName = "k40t_video";
constexpr const char* kVideoTransportPublisherPlugin = "image_transport/k40t_video_pub";

}  // namespace k40t::driver
