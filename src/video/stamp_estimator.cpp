#include "k40t_driver/video/stamp_estimator.h"

#include <algorithm>
#include <cmath>

namespace k40t::video {

void StampEstimator::reset() {
  last_pts_us_.reset();
  offsets_.clear();
}

int64_t StampEstimator::stamp(int64_t received_us, std::optional<double> pts_ms) {
  const int64_t latency_us = std::llround(options_.latency_s * 1e6);
  if (!options_.use_presentation_time || !pts_ms || !std::isfinite(*pts_ms)) {
    reset();
    return received_us - latency_us;
  }
  const int64_t pts_us = std::llround(*pts_ms * 1000);
  const int64_t max_jump_us = std::llround(options_.max_pts_jump_s * 1e6);
  if (last_pts_us_ && (pts_us <= *last_pts_us_ || pts_us - *last_pts_us_ > max_jump_us)) {
    offsets_.clear();
  }
  last_pts_us_ = pts_us;

  const int64_t window_us = std::llround(options_.window_s * 1e6);
  while (!offsets_.empty() && received_us - offsets_.front().first > window_us) {
    offsets_.pop_front();
  }
  offsets_.emplace_back(received_us, received_us - pts_us);
  int64_t min_offset = offsets_.back().second;
  for (const auto& entry : offsets_) min_offset = std::min(min_offset, entry.second);
  return pts_us + min_offset - latency_us;
}

}  // namespace k40t::video
