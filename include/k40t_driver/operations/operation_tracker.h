// The life of one long pod operation (format, zoom, calibration...) as the driver sees it: the
// request goes out, its ACK comes back, status frames report progress until one reports the end,
// or nothing ends it before the timeout. ROS-free and clock-free (times are arguments in seconds
// of any monotonic clock), so every decision is unit-tested; the actionlib glue (src/ros/) only
// feeds it and publishes what it says.
//
// Rules:
//   - a refused or unanswered request ends the operation at once, with the pod's text;
//   - an end reported by a status frame before the ACK has arrived (the frames and the ACK travel
//     on different threads) waits for the ACK: success needs both;
//   - nothing changes after the end (a late status frame or ACK is ignored);
//   - the timeout counts from the start and names what was awaited and the last status seen.
#pragma once

#include <cstdint>
#include <string>
#include <utility>

#include "k40t_driver/protocol/result.h"

namespace k40t::operations {

enum class Phase {
  kRunning,
  kSucceeded,
  kFailed,     // the pod refused, did not answer, or reported a failure
  kTimedOut,   // no end within the timeout
  kCancelled,  // the caller cancelled (the glue stopped what the pod can stop)
};
const char* to_string(Phase phase);

// What one status frame says about the operation.
struct Step {
  Phase phase = Phase::kRunning;  // kRunning, kSucceeded or kFailed
  std::string text;               // the state's text, e.g. "formatting"
};

class OperationTracker {
 public:
  // `what` names the operation in reasons ("SD format"); `awaited` names what ends it
  // ("SD format status 0x02030D 'done'"). Starts at `now_s`.
  OperationTracker(std::string what, std::string awaited, double timeout_s, double now_s);

  // The request's ACK: ok, or refused/unanswered with the session's text.
  void acknowledged(bool ok, const std::string& message);
  // A status frame about this operation.
  void report(const Step& step);
  void cancel(const std::string& how);
  // Operations whose end may come without a status frame (docs/protocol/decisions.md
  // #conventions, calibration_end):
  //   - the OK ACK itself ends it, with `text`;
  //   - or it ends as succeeded `quiet_s` after the OK ACK was first seen by check() if no status
  //     frame has been reported by then.
  void end_with_ack(std::string text);
  void end_if_quiet_after_ack(double quiet_s, std::string text);
  // Decides the timeout (and a quiet end); returns the phase.
  Phase check(double now_s);

  Phase phase() const { return phase_; }
  bool done() const { return phase_ != Phase::kRunning; }
  bool acked() const { return acked_; }
  const std::string& reason() const { return reason_; }            // why it ended; "" while running
  const std::string& status_text() const { return status_text_; }  // latest status ("" if none)
  int reports() const { return reports_; }
  double elapsed_s(double now_s) const { return now_s - start_s_; }
  double timeout_s() const { return timeout_s_; }

 private:
  void end(Phase phase, std::string reason);

  std::string what_;
  std::string awaited_;
  double timeout_s_;
  double start_s_;
  Phase phase_ = Phase::kRunning;
  bool acked_ = false;
  bool success_reported_ = false;  // an end seen before the ACK
  std::string success_text_;
  std::string reason_;
  std::string status_text_;
  int reports_ = 0;
  double quiet_s_ = -1;  // < 0: no quiet end
  std::string quiet_text_;
  double acked_seen_s_ = -1;  // when check() first saw the ACK
};

// The timeout a goal asks for: 0 means `default_s`; negative or not finite is an error (nothing
// is sent). Returns the timeout or an error naming the field.
struct TimeoutChoice {
  bool ok = false;
  double seconds = 0;
  std::string error;
};
TimeoutChoice choose_timeout(double requested_s, double default_s);

// What every long operation shares: the OperationTracker made from its name and what ends it
// (see OperationTracker's constructor), which the ROS glue reads through tracker().
class TrackedOperation {
 public:
  OperationTracker& tracker() { return tracker_; }
  const OperationTracker& tracker() const { return tracker_; }

 protected:
  TrackedOperation(std::string what, std::string awaited, double timeout_s, double now_s)
      : tracker_(std::move(what), std::move(awaited), timeout_s, now_s) {}

  // For create(): `make(seconds)` with the timeout the goal asks for (choose_timeout), or the
  // timeout's error.
  template <class Make>
  static auto with_timeout(double requested_s, double default_s, Make make)
      -> Result<decltype(make(0.0))> {
    const TimeoutChoice timeout = choose_timeout(requested_s, default_s);
    if (!timeout.ok) return Status::fail(timeout.error);
    return make(timeout.seconds);
  }

 private:
  OperationTracker tracker_;
};

}  // namespace k40t::operations
