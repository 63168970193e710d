#include "k40t_driver/skyport/photo_progress.h"

#include <algorithm>

namespace k40t::driver::skyport {

namespace {

// CameraStatus photo modes and PhotoStatus states (msg/*.msg), kept here so the bridge needs no
// ROS header.
constexpr uint8_t kModeBurst = 1, kModeTimelapse = 2;
constexpr uint8_t kStateSingle = 1, kStateBurst = 2, kStateTimelapse = 3,
                  kStateSingleInProgress = 5;

// A "taking photo" refusal proves the pod busy at that moment; the photo state says so for this
// long after it (DJI Pilot polls about once a second and retries later).
constexpr auto kBusyAfterRefusal = std::chrono::milliseconds(500);

}  // namespace

void PhotoProgress::started(const PodSnapshot& pod, Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  kind_ = pod.photo_mode == kModeBurst       ? Kind::kBurst
          : pod.photo_mode == kModeTimelapse ? Kind::kInterval
                                             : Kind::kSingle;
  status_count_at_start_ = pod.photo_status_count;
  busy_until_ = now + storing_bound_;
}

void PhotoProgress::capture_answered(const PodCall& call, Clock::time_point now) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (call.ok) {
    kind_ = Kind::kNone;  // the pod refuses capture commands while it takes or stores a photo
  } else if (call.photo_in_progress) {
    if (kind_ == Kind::kNone) kind_ = Kind::kSingle;  // started by someone else: still busy
    busy_until_ = std::max(busy_until_, now + kBusyAfterRefusal);
  }
}

psdk::ShootPhotoStateAck PhotoProgress::state(const PodSnapshot& pod, Clock::time_point now) const {
  psdk::ShootPhotoStateAck ack;
  std::lock_guard<std::mutex> lock(mutex_);
  if (kind_ == Kind::kNone) return ack;
  if (pod.photo_status_count > status_count_at_start_) {
    // The pod reported on this photo: its word wins.
    ack.state.shooting_single =
        pod.photo_state == kStateSingle || pod.photo_state == kStateSingleInProgress;
    ack.state.shooting_burst = pod.photo_state == kStateBurst;
    ack.state.shooting_interval = pod.photo_state == kStateTimelapse;
    return ack;
  }
  switch (kind_) {
    case Kind::kSingle:
      ack.state.shooting_single = now < busy_until_;
      break;
    case Kind::kBurst:
      ack.state.shooting_burst = true;
      break;
    case Kind::kInterval:
      ack.state.shooting_interval = true;
      break;
    case Kind::kNone:
      break;
  }
  return ack;
}

}  // namespace k40t::driver::skyport
