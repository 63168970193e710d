// A pod setting the bridge set and the pod accepted, answered by the getters until the pod's own
// status report agrees. The pod reports its camera state once a second (camera/status), so a get
// right after a set would otherwise read the value from before the set (DJI Pilot, and
// skyport_sim's `check camera`, read the work mode back at once). A report that still disagrees
// after `hold` wins: the pod changed its mind, or another client changed the setting since.
// ROS-free.
#pragma once

#include <chrono>
#include <optional>

namespace k40t::driver::skyport {

template <class T>
class CommandedValue {
 public:
  using Clock = std::chrono::steady_clock;

  explicit CommandedValue(Clock::duration hold) : hold_(hold) {}

  // The pod accepted `value` at `now`.
  void accepted(const T& value, Clock::time_point now) {
    value_ = value;
    at_ = now;
  }
  // A status report: the command is done once the report agrees, or once `hold` passed.
  void reported(const T& value, Clock::time_point now) {
    if (value_ && (*value_ == value || now - at_ > hold_)) value_.reset();
  }
  // What a getter answers, given the newest report.
  T answer(const T& reported, Clock::time_point now) const {
    return value_ && now - at_ <= hold_ ? *value_ : reported;
  }

 private:
  Clock::duration hold_;
  std::optional<T> value_;
  Clock::time_point at_;
};

}  // namespace k40t::driver::skyport
