// The newest-frame grabber: one thread reads the stream as fast as it arrives and keeps only the
// latest decoded frame; consumers take that one and never see a backlog (frames they were too
// slow for are simply replaced). When the stream fails — open error, read error, end of stream,
// or silence beyond the read timeout — the capture is released and opened again after the
// transport layer's back-off (transport/backoff.h), which restarts from its initial delay once a
// frame has come.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>

#include <opencv2/core.hpp>

#include "k40t_driver/transport/transport.h"
#include "k40t_driver/video/capture_options.h"
#include "k40t_driver/video/frame_source.h"

namespace k40t::video {

// The frame as BGR (a conversion for I420, the same pixels otherwise).
cv::Mat to_bgr(const GrabbedFrame& frame);

// The video default: 250 ms, doubling, at most 4 s between attempts.
transport::ReconnectPolicy default_video_reconnect_policy();

class FrameGrabber : public FrameSource {
 public:
  FrameGrabber(const CaptureOptions& capture,
               const transport::ReconnectPolicy& reconnect = default_video_reconnect_policy());
  ~FrameGrabber() override;  // stop()
  FrameGrabber(const FrameGrabber&) = delete;
  FrameGrabber& operator=(const FrameGrabber&) = delete;

  void start() override;
  // Ends the thread. A read blocked inside the back-end past every timeout (possible only with
  // OpenCV's default settings) is left to finish on its own, detached.
  void stop() override;

  // Closes the capture after the frame being read and opens it again at once. For the FFmpeg
  // back-end after the stream's frame size changed: OpenCV 4.6 keeps converting to the first size
  // there ("Slice parameters ... are invalid") and repeats the last good frame for ever.
  void restart() override;

  // The newest frame with a sequence above `after`, waiting up to `timeout` for one.
  std::optional<GrabbedFrame> wait_newer(uint64_t after,
                                         std::chrono::milliseconds timeout) override;
  GrabberStats stats() const override;

  struct State;

 private:
  std::shared_ptr<State> state_;
};

}  // namespace k40t::video
