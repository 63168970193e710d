// Acquisition stamps for decoded frames. The pod sends no capture time we can read, so a frame's
// stamp is its reception time minus the pipeline latency (pod capture + encode + network +
// decode), which is a configured estimate (`latency_s`, see docs/video.md for how to measure it).
//
// Reception times jitter with scheduling and decode time. When the back-end gives presentation
// times (the RTP timestamps, mapped), the estimator uses them to take that jitter out: the offset
// between reception and presentation time is tracked as its minimum over the last `window_s`
// (the least-delayed frame), and each frame is stamped presentation + that offset - latency. A
// presentation time that goes backwards or jumps (a reconnect, a new stream) restarts the window;
// without presentation times, frames are stamped reception - latency.
//
// Every stamp is at most reception - latency: the estimate never claims a frame is newer than it
// can be.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <utility>

namespace k40t::video {

struct StampOptions {
  double latency_s = 0.0;
  double window_s = 3.0;
  bool use_presentation_time = false;  // off by default: see config/video.yaml
  double max_pts_jump_s = 2.0;  // larger steps between frames restart the mapping
};

class StampEstimator {
 public:
  explicit StampEstimator(const StampOptions& options = {}) : options_(options) {}

  // Microseconds since the epoch, on the clock `received_us` is on.
  int64_t stamp(int64_t received_us, std::optional<double> pts_ms);
  void reset();

 private:
  StampOptions options_;
  std::optional<int64_t> last_pts_us_;
  std::deque<std::pair<int64_t, int64_t>> offsets_;  // (received, received - pts), oldest first
};

}  // namespace k40t::video
