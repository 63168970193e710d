#include "k40t_driver/video/frame_grabber.h"

#include <algorithm>
#include <mutex>
#include <thread>
#include <utility>

#include <opencv2/imgproc.hpp>

#include "k40t_driver/transport/backoff.h"
#include "k40t_driver/transport/thread_name.h"
#include "k40t_driver/video/capture_open.h"
#include "k40t_driver/video/opencv_log_scope.h"
#include "k40t_driver/video/source_state.h"

namespace k40t::video {

using Clock = std::chrono::steady_clock;

cv::Mat to_bgr(const GrabbedFrame& frame) {
  if (!frame.i420) return frame.pixels;
  cv::Mat bgr;
  cv::cvtColor(frame.pixels, bgr, cv::COLOR_YUV2BGR_I420);
  return bgr;
}

// Shared by the grabber and its thread (source_state.h).
struct FrameGrabber::State : SourceState {
  CaptureOptions capture;
  transport::ReconnectPolicy reconnect;
  uint64_t sequence = 0;

  void publish(cv::Mat pixels, int64_t received_us, std::optional<double> pts_ms) {
    GrabbedFrame frame;
    frame.i420 = delivers_i420(capture) && pixels.type() == CV_8UC1;
    frame.size = frame.i420 ? cv::Size(pixels.cols, pixels.rows * 2 / 3) : pixels.size();
    frame.pixels = std::move(pixels);
    frame.received_us = received_us;
    frame.pts_ms = pts_ms;
    {
      std::lock_guard<std::mutex> lock(mutex);
      frame.sequence = ++sequence;
      latest = std::move(frame);
      ++stats.frames;
      stats.streaming = true;
      stats.last_frame = Clock::now();
    }
    changed.notify_all();
  }

  enum class StreamEnd { kFailed, kRestart, kStopped };

  // Reads until the stream fails, a restart is asked for or the grabber stops. `any` tells
  // whether at least one frame came.
  StreamEnd stream(cv::VideoCapture& capture, bool& any) {
    any = false;
    while (is_running()) {
      if (take_restart()) return StreamEnd::kRestart;
      cv::Mat pixels;  // a new buffer each time: the previous frame may still be in use
      bool ok = false;
      try {
        ok = capture.read(pixels);
      } catch (const cv::Exception&) {
        ok = false;
      }
      const int64_t received_us = std::chrono::duration_cast<std::chrono::microseconds>(
                                      std::chrono::system_clock::now().time_since_epoch())
                                      .count();
      if (!ok || pixels.empty()) {
        failed(true, "the stream ended or stalled (no frame within the read timeout)");
        return StreamEnd::kFailed;
      }
      if (!pixels.u) pixels = pixels.clone();  // pointing into the back-end's own buffer
      double pts = 0;
      {
        OpenCvLogScope live_stream;  // the "may be unreliable" note is about seeking files
        pts = capture.get(cv::CAP_PROP_POS_MSEC);
      }
      publish(std::move(pixels), received_us, pts > 0 ? std::optional<double>(pts) : std::nullopt);
      any = true;
    }
    return StreamEnd::kStopped;
  }

  void run() {
    transport::name_this_thread("k40t_vgrab");
    transport::Backoff backoff(reconnect);
    bool ever_opened = false;
    while (is_running()) {
      auto opened = open_capture(capture);
      if (opened) {
        if (ever_opened) {
          std::lock_guard<std::mutex> lock(mutex);
          ++stats.reconnects;
        }
        ever_opened = true;
        bool any = false;
        const StreamEnd end = stream(*opened.value(), any);
        opened.value()->release();
        if (any) backoff.reset();
        if (end == StreamEnd::kRestart) continue;
      } else {
        failed(false, opened.error());
      }
      if (!pause(backoff.next())) break;
    }
    finish_thread();
  }
};

transport::ReconnectPolicy default_video_reconnect_policy() {
  transport::ReconnectPolicy policy;
  policy.initial_delay = std::chrono::milliseconds(250);
  policy.max_delay = std::chrono::milliseconds(4000);
  policy.factor = 2.0;
  return policy;
}

FrameGrabber::FrameGrabber(const CaptureOptions& capture,
                           const transport::ReconnectPolicy& reconnect)
    : state_(std::make_shared<State>()) {
  state_->capture = capture;
  state_->reconnect = reconnect;
}

FrameGrabber::~FrameGrabber() {
  stop();
}

void FrameGrabber::start() {
  start_source_thread(state_);
}

void FrameGrabber::stop() {
  // Every timeout the tuned configurations set ends a blocked read well within this.
  state_->stop(std::chrono::duration<double>(state_->capture.open_timeout_s +
                                             state_->capture.read_timeout_s + 1.0));
}

std::optional<GrabbedFrame> FrameGrabber::wait_newer(uint64_t after,
                                                     std::chrono::milliseconds timeout) {
  return state_->wait_newer(after, timeout);
}

void FrameGrabber::restart() {
  state_->request_restart();
}

GrabberStats FrameGrabber::stats() const {
  return state_->stats_now();
}

}  // namespace k40t::video
