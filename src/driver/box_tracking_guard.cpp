#include "k40t_driver/driver/box_tracking_guard.h"

namespace k40t::driver {

namespace p = protocol;

void BoxTrackingGuard::frame_sent(const p::FrameView& frame, const p::CodecOptions& codec) {
  std::lock_guard<std::mutex> lock(mutex_);
  switch_.sent(frame, codec);
}

void BoxTrackingGuard::frame_received(const p::FrameView& frame, const p::CodecOptions& codec) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (const auto accepted = switch_.accepted(frame, codec))
    tracking_ = accepted->tracking == p::FeatureSwitch::kOn;
}

bool BoxTrackingGuard::tracking() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return tracking_;
}

p::BoxTrackingRequest box_tracking_off() {
  p::BoxTrackingRequest off;
  off.tracking = p::FeatureSwitch::kOff;
  return off;
}

}  // namespace k40t::driver
