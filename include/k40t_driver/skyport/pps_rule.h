// The UTC push's 500 ms rule (3.3.10), ROS-free: a UTC push that comes more than 500 ms after the
// PPS rising edge it describes is to be discarded.
//
// With a PPS source (the bridge's `pps_topic`) the edge's local time is known: judge_utc_push().
// Without one (the default) the rule still applies, relative to the most punctual push
// (UtcPushLateness): each push names the UTC instant of its edge, so its local receipt time minus
// that instant is its edge-to-receipt delay plus the (constant) offset between the two clocks. The
// smallest such value over the last minute is that offset plus the least delay, which is not
// negative; a push whose value exceeds the smallest by more than 500 ms therefore arrived more
// than 500 ms after its edge, whatever the offset. Pushes only a little late may pass (the least
// delay is unknown), but none is dropped wrongly.
#pragma once

#include <deque>
#include <optional>
#include <utility>

namespace k40t::driver::skyport {

constexpr double kUtcPushDeadline_s = 0.5;

enum class UtcPushVerdict { kUse, kLate, kNoEdge };

// `edge_s`: local time of the newest PPS rising edge (none yet: kNoEdge); `received_s`: local
// time the push arrived. A push before its edge (clock jitter) is used.
inline UtcPushVerdict judge_utc_push(std::optional<double> edge_s, double received_s) {
  if (!edge_s) return UtcPushVerdict::kNoEdge;
  return received_s - *edge_s > kUtcPushDeadline_s ? UtcPushVerdict::kLate : UtcPushVerdict::kUse;
}

class UtcPushLateness {
 public:
  struct Judgement {
    UtcPushVerdict verdict = UtcPushVerdict::kUse;
    // How much later than the most punctual push of the window this one came (>= 0): its edge
    // was at least that long before its receipt.
    double excess_delay_s = 0;
  };

  // `window_s`: how far back the most punctual push is looked for (local clock drift over it must
  // stay far below 500 ms). After `clock_step_after` late pushes in a row the window starts again:
  // one of the two clocks stepped (a UTC correction), and every push would be late otherwise.
  explicit UtcPushLateness(double window_s = 60.0, int clock_step_after = 3)
      : window_s_(window_s), clock_step_after_(clock_step_after) {}

  // `utc_s`: the push's UTC time (seconds, fraction included); `received_s`: its local receipt
  // time on a monotonic clock.
  Judgement judge(double utc_s, double received_s) {
    while (!window_.empty() && received_s - window_.front().first > window_s_) window_.pop_front();
    const double offset = received_s - utc_s;
    window_.emplace_back(received_s, offset);
    double least = offset;
    for (const auto& entry : window_) least = entry.second < least ? entry.second : least;
    Judgement out;
    out.excess_delay_s = offset - least;
    if (out.excess_delay_s <= kUtcPushDeadline_s) {
      late_in_a_row_ = 0;
      return out;
    }
    out.verdict = UtcPushVerdict::kLate;
    if (++late_in_a_row_ >= clock_step_after_) {  // a clock step: this push starts a new window
      window_.clear();
      window_.emplace_back(received_s, offset);
      late_in_a_row_ = 0;
    }
    return out;
  }

 private:
  double window_s_;
  int clock_step_after_;
  int late_in_a_row_ = 0;
  std::deque<std::pair<double, double>> window_;  // (receipt, receipt - UTC)
};

}  // namespace k40t::driver::skyport
