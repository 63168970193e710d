// The UTC push's 500 ms rule (3.3.10), ROS-free: a UTC push that comes more than 500 ms after the
// PPS rising edge it describes is to be discarded. The edge's local time comes from a PPS source
// (the bridge's `pps_topic`); without one there is nothing to measure against.
#pragma once

#include <optional>

namespace k40t::driver::skyport {

constexpr double kUtcPushDeadline_s = 0.5;

enum class UtcPushVerdict { kUse, kLate, kNoEdge };

// `edge_s`: local time of the newest PPS rising edge (none yet: kNoEdge); `received_s`: local
// time the push arrived. A push before its edge (clock jitter) is used.
inline UtcPushVerdict judge_utc_push(std::optional<double> edge_s, double received_s) {
  if (!edge_s) return UtcPushVerdict::kNoEdge;
  return received_s - *edge_s > kUtcPushDeadline_s ? UtcPushVerdict::kLate : UtcPushVerdict::kUse;
}

}  // namespace k40t::driver::skyport
