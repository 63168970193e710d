// What the video node takes decoded frames from: the newest-frame grabber (OpenCV videoio,
// frame_grabber.h) or the access-unit source (native GStreamer, access_unit_source.h), which
// also hands on the stream's encoded access units and decodes only on demand.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

namespace k40t::video {

struct GrabbedFrame {
  cv::Mat pixels;  // as read: BGR (CV_8UC3), or I420 (CV_8UC1, height * 3 / 2 rows) if `i420`
  // What keeps `pixels` alive when they are a decoder's buffer (not a copy); keep the frame, not
  // only the Mat, while using them.
  std::shared_ptr<const uint8_t> memory;
  bool i420 = false;
  cv::Size size;                 // the picture's size
  int64_t received_us = 0;       // system clock when it came off the stream
  std::optional<double> pts_ms;  // the back-end's presentation time, if it gives one
  uint64_t sequence = 0;         // increasing over the source's life, across reconnects
};

struct GrabberStats {
  uint64_t frames = 0;         // frames (access units) read
  uint64_t read_errors = 0;    // reads that failed on an open stream (decode error, EOS, stall)
  uint64_t open_failures = 0;  // opens that failed
  uint64_t reconnects = 0;     // opens after the first successful one
  bool streaming = false;      // open, and the last read succeeded
  std::optional<std::chrono::steady_clock::time_point> last_frame;
  std::string last_error;
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  virtual void start() = 0;
  virtual void stop() = 0;
  // Closes the stream after the current frame and opens it again at once.
  virtual void restart() = 0;
  // The newest decoded frame with a sequence above `after`, waiting up to `timeout` for one.
  virtual std::optional<GrabbedFrame> wait_newer(uint64_t after,
                                                 std::chrono::milliseconds timeout) = 0;
  virtual GrabberStats stats() const = 0;
};

}  // namespace k40t::video
