#include "k40t_driver/operations/capture_mode_guard.h"

#include <string>

namespace k40t::operations {

namespace p = protocol;

void CaptureModeGuard::frame_sent(const p::FrameView& frame, const p::CodecOptions& codec) {
  std::lock_guard<std::mutex> lock(mutex_);
  switch_.sent(frame, codec);
}

void CaptureModeGuard::frame_received(const p::FrameView& frame, const p::CodecOptions& codec,
                                      Clock::time_point now) {
  if (frame.header.message_id == p::CameraSystemStatus::kId) {
    Result<p::CameraSystemStatus> status = p::decode_payload<p::CameraSystemStatus>(frame, codec);
    if (!status) return;
    std::lock_guard<std::mutex> lock(mutex_);
    photo_mode_ = status->photo_mode;
    const bool settling = switched_at_ && now - *switched_at_ < kSettle;
    if (!settling || status->capture_mode == mode_) mode_ = status->capture_mode;
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (const auto accepted = switch_.accepted(frame, codec)) {
    mode_ = accepted->mode;
    switched_at_ = now;
  }
}

Status CaptureModeGuard::allows(p::CaptureMode needed, const char* request) const {
  std::optional<p::CaptureMode> mode;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    mode = mode_;
  }
  if (!mode || *mode == needed) return Status::ok();
  const char* const have = *mode == p::CaptureMode::kVideo ? "video" : "photo";
  const char* const want = needed == p::CaptureMode::kVideo ? "video" : "photo";
  return Status::fail(std::string("not sent: the camera is in ") + have + " mode, and in " + have +
                      " mode the pod does not answer " + request +
                      " (section 3.2.4.1); switch to " + want +
                      " mode first (reconfigure parameter camera_mode, 0x000300)");
}

Status CaptureModeGuard::allows_stop(p::PhotoMode2 reading) const {
  std::optional<p::PhotoMode> photo_mode;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    photo_mode = photo_mode_;
  }
  if (reading != p::PhotoMode2::kSelfTimer || photo_mode != p::PhotoMode::kTimeLapse)
    return Status::ok();
  return Status::fail(
      "not sent: photo mode 2 is a self-timer on this pod (parameter photo_mode_2: self_timer, "
      "docs/protocol/decisions.md#conventions): it takes one photo after the interval and has "
      "nothing to stop; \"stop\" is valid in burst mode only (section 3.2.4.3)");
}

std::string CaptureModeGuard::unanswered(p::CaptureMode needed, const char* request,
                                         const std::string& no_ack) {
  const char* const other = needed == p::CaptureMode::kVideo ? "photo" : "video";
  return no_ack + "; in " + other + " mode the pod does not answer " + request +
         " (section 3.2.4.1): check the camera's mode (camera/status, reconfigure parameter "
         "camera_mode)";
}

}  // namespace k40t::operations
