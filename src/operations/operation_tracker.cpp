#include "k40t_driver/operations/operation_tracker.h"

#include <cmath>
#include <cstdio>
#include <utility>

#include "k40t_driver/codec/enum_names.h"

namespace k40t::operations {

namespace {
std::string seconds_text(double s) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", s);
  return text;
}
}  // namespace

const char* to_string(Phase phase) {
  static constexpr EnumName<Phase> kNames[] = {{Phase::kRunning, "running"},
                                               {Phase::kSucceeded, "succeeded"},
                                               {Phase::kFailed, "failed"},
                                               {Phase::kTimedOut, "timed out"},
                                               {Phase::kCancelled, "cancelled"}};
  return name_in(kNames, phase);
}

OperationTracker::OperationTracker(std::string what, std::string awaited, double timeout_s,
                                   double now_s)
    : what_(std::move(what)),
      awaited_(std::move(awaited)),
      timeout_s_(timeout_s),
      start_s_(now_s) {}

void OperationTracker::end(Phase phase, std::string reason) {
  phase_ = phase;
  reason_ = std::move(reason);
}

void OperationTracker::acknowledged(bool ok, const std::string& message) {
  if (done()) return;
  if (!ok) return end(Phase::kFailed, what_ + " refused or not acknowledged: " + message);
  acked_ = true;
  if (success_reported_) end(Phase::kSucceeded, what_ + ": " + success_text_);
}

void OperationTracker::report(const Step& step) {
  if (done()) return;
  ++reports_;
  status_text_ = step.text;
  if (step.phase == Phase::kFailed) return end(Phase::kFailed, what_ + " failed: " + step.text);
  if (step.phase != Phase::kSucceeded) return;
  if (acked_) return end(Phase::kSucceeded, what_ + ": " + step.text);
  success_reported_ = true;  // the ACK decides
  success_text_ = step.text;
}

void OperationTracker::cancel(const std::string& how) {
  if (done()) return;
  end(Phase::kCancelled, what_ + " cancelled" + (how.empty() ? "" : ": " + how));
}

void OperationTracker::end_with_ack(std::string text) {
  if (done()) return;
  if (acked_) return end(Phase::kSucceeded, what_ + ": " + text);
  success_reported_ = true;
  success_text_ = std::move(text);
}

void OperationTracker::end_if_quiet_after_ack(double quiet_s, std::string text) {
  quiet_s_ = quiet_s;
  quiet_text_ = std::move(text);
}

Phase OperationTracker::check(double now_s) {
  if (!done() && acked_ && quiet_s_ >= 0) {
    if (acked_seen_s_ < 0) acked_seen_s_ = now_s;
    if (reports_ == 0 && now_s - acked_seen_s_ >= quiet_s_)
      end(Phase::kSucceeded, what_ + ": " + quiet_text_);
  }
  if (done() || elapsed_s(now_s) < timeout_s_) return phase_;
  const std::string last = !acked_                ? "the request was not acknowledged yet"
                           : status_text_.empty() ? "no status frame received"
                                                  : "last status '" + status_text_ + "'";
  end(Phase::kTimedOut, what_ + " timed out after " + seconds_text(timeout_s_) + " waiting for " +
                            awaited_ + " (" + last + ")");
  return phase_;
}

TimeoutChoice choose_timeout(double requested_s, double default_s) {
  TimeoutChoice choice;
  if (!std::isfinite(requested_s) || requested_s < 0) {
    choice.error = "field 'timeout' must be 0 (the default, " + seconds_text(default_s) +
                   ") or a positive number of seconds, got " + std::to_string(requested_s);
    return choice;
  }
  choice.ok = true;
  choice.seconds = requested_s == 0 ? default_s : requested_s;
  return choice;
}

}  // namespace k40t::operations
