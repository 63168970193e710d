// The image_transport transport of encoded video (k40t_driver/CompressedVideo): its name (the
// topic is <base>/k40t_video, e.g. image_raw/k40t_video) and its lookup name
// (k40t_video_plugins.xml declares image_transport/k40t_video_pub and _sub).
#pragma once

namespace k40t::driver {

constexpr const char* kVideoTransportName = "k40t_video";
// How image_transport's disable_pub_plugins parameter names the publisher (no "_pub").
constexpr const char* kVideoTransportLookupName = "image_transport/k40t_video";

}  // namespace k40t::driver
