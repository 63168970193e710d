#pragma once

#include <mutex>

#include <opencv2/core/utils/logger.hpp>

namespace k40t::video {

// Raises OpenCV's (process-wide) log level to ERROR while at least one scope lives. Used only
// around the calls where OpenCV warns about what a live RTSP stream simply does not have: a
// duration, a seekable position ("unable to query duration of stream", "Cannot query video
// position", and the note that CAP_PROP_POS_MSEC "may be unreliable" when seeking). Those lines are
// not warnings for a live stream, and printed on every start they hide the real ones. Real
// failures still surface: open() and read() return false and the grabber reports that itself.
// Counted, so that scopes of several grabbers in one process (a nodelet manager) restore the
// level the process had, whatever order they end in.
class OpenCvLogScope {
 public:
  OpenCvLogScope() {
    std::lock_guard<std::mutex> lock(state().mutex);
    if (state().depth++ == 0) {
      state().saved = cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_ERROR);
    }
  }
  ~OpenCvLogScope() {
    std::lock_guard<std::mutex> lock(state().mutex);
    if (--state().depth == 0) cv::utils::logging::setLogLevel(state().saved);
  }
  OpenCvLogScope(const OpenCvLogScope&) = delete;
  OpenCvLogScope& operator=(const OpenCvLogScope&) = delete;

 private:
  struct State {
    std::mutex mutex;
    int depth = 0;
    cv::utils::logging::LogLevel saved = cv::utils::logging::LOG_LEVEL_WARNING;
  };
  static State& state() {
    static State s;
    return s;
  }
};

}  // namespace k40t::video
