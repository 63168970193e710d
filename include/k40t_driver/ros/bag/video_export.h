// `k40t bag --video FILE / --video-frames DIR`: a recorded passthrough topic
// (k40t_driver/CompressedVideo, e.g. /k40t/image_raw/k40t_video) out of a bag, without ROS
// running:
//   FILE (.mp4, .m4v, .mkv)  the access units as they are, muxed (container_writer.h): no
//                            re-encoding, playable in any player, time = the messages' stamps;
//   DIR                      every frame decoded to DIR/frame_NNNNNN.png (bgr8 pictures, lossless)
//                            and DIR/frames.csv: frame, stamp_ns (header.stamp), key_frame, file.
// Both start at the topic's first key frame (what comes before cannot be decoded).
#pragma once

#include <cstdint>
#include <string>

#include "k40t_driver/protocol/result.h"

namespace k40t::driver {

struct VideoExportOptions {
  std::string topic;       // empty: the bag's only CompressedVideo topic
  std::string video_file;  // empty: none
  std::string frames_dir;  // empty: none
};

struct VideoExportSummary {
  std::string topic;
  std::string format;     // h264 / h265
  uint64_t messages = 0;  // read from the topic
  uint64_t written = 0;   // access units in the video file
  uint64_t frames = 0;    // PNG files
  double duration_s = 0;  // first key frame to last message, by stamp
};

Result<VideoExportSummary> export_video(const std::string& bag_path,
                                        const VideoExportOptions& options);

}  // namespace k40t::driver
