// A machine-readable stamp drawn into every simulated video frame, so that whoever receives the
// frame after encoding, RTSP, decoding and ROS can tell which frame it is and when it was
// rendered: end-to-end latency and dropped/duplicated frames are measured from the pixels alone.
//
// Layout: 16 bytes (magic 'K', version 1, uint32 frame counter, int64 render time in microseconds
// since the Unix epoch (system clock, the clock ros::Time::now() reads), uint16 CRC-16/MCRF4XX
// of the first 14 bytes), little-endian, drawn most significant bit first as a 32 x 4 grid of
// 8 x 8 pixel black/white blocks in the frame's top-left corner (256 x 32 pixels). Blocks of
// 8 x 8 aligned with the encoder's transform blocks survive H.264 at the stream's bitrates; the
// decoder reads each block's centre and the CRC rejects anything misread.
#pragma once

#include <cstdint>
#include <optional>

#include <opencv2/core.hpp>

namespace k40t::sim::video {

struct FrameStamp {
  uint32_t counter = 0;
  int64_t render_time_us = 0;
};

constexpr int kStampBlockPx = 8;
constexpr int kStampColumns = 32;
constexpr int kStampRows = 4;
constexpr int kStampWidthPx = kStampBlockPx * kStampColumns;
constexpr int kStampHeightPx = kStampBlockPx * kStampRows;

// Draws `stamp` into the top-left corner of `bgr` (CV_8UC3, at least 256 x 32 pixels); returns
// false, drawing nothing, when the image is of another type or too small.
bool draw_frame_stamp(cv::Mat& bgr, const FrameStamp& stamp);

// Reads the stamp back from a decoded frame (CV_8UC3 BGR or CV_8UC1 grey); nothing when the
// frame carries none or it was damaged (wrong magic, version or CRC).
std::optional<FrameStamp> read_frame_stamp(const cv::Mat& image);

// Microseconds since the Unix epoch on the system clock.
int64_t system_time_us();

}  // namespace k40t::sim::video
