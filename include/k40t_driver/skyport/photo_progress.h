// Whether a photo the bridge started is still being taken or stored by the pod, for PSDK's
// "photo state" (0x04/0x04), ROS-free. The pod says nothing while it stores a single photo (its
// status frames cover bursts and time-lapses, and single shots only when it is configured to send
// them), but it refuses capture commands meanwhile ("taking photo", 0x0203). What the bridge can
// observe, in order of trust:
//   1. a photo/status frame that came after the shoot: an in-progress state (single, burst,
//      time-lapse) means shooting; a final one (taken, stopped, failed, card errors) means done;
//   2. a capture command the pod refused with "taking photo": still busy at that moment;
//      one it accepted (mode change, record, photo mode, format, another photo): not busy;
//   3. for a single photo with neither: busy for `storing_bound` after the pod accepted the shoot.
// Bursts and time-lapses end only by 1 or 2 (the pod's status frames report them).
#pragma once

#include <chrono>
#include <cstdint>
#include <mutex>

#include "k40t_driver/psdk/commands/camera_capture.h"
#include "k40t_driver/skyport/pod_port.h"

namespace k40t::driver::skyport {

class PhotoProgress {
 public:
  using Clock = std::chrono::steady_clock;

  explicit PhotoProgress(Clock::duration storing_bound) : storing_bound_(storing_bound) {}

  // The pod accepted a shoot; `pod` is its state then (photo mode, photo/status count).
  void started(const PodSnapshot& pod, Clock::time_point now);
  // The pod answered a capture command: refused because it is taking a photo, or accepted.
  void capture_answered(const PodCall& call, Clock::time_point now);
  // PSDK's photo state now.
  psdk::ShootPhotoStateAck state(const PodSnapshot& pod, Clock::time_point now) const;

 private:
  enum class Kind : uint8_t { kNone, kSingle, kBurst, kInterval };

  mutable std::mutex mutex_;
  Clock::duration storing_bound_;
  Kind kind_ = Kind::kNone;
  uint64_t status_count_at_start_ = 0;
  Clock::time_point busy_until_{};  // single photos without status frames
};

}  // namespace k40t::driver::skyport
