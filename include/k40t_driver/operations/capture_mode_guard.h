// Photos and recordings need the camera in the matching capture mode. Section 3.2.4.1 (0x000300,
// note): "拍照模式下不响应录像指令; 录像模式下不响应拍照指令" - in photo mode the pod does not
// answer a record request, in video mode it does not answer a photo request. Sent anyway, the
// caller would get "no ACK ..." and no hint why; so the services look at the camera's mode and
// refuse, naming it, before anything is sent. The same report's photo mode tells whether a photo
// "stop" can mean anything (allows_stop()).
//
// The mode is what the pod last said: 0x000003 byte 1 (1 Hz), or a 0x000300 it accepted (its ACK
// 0x010300 with code OK), whichever is later. A 0x000003 that disagrees within kSettleS of an
// accepted switch is taken for one made before it and ignored, so that a record right after
// switching to video mode is not refused on the strength of an old report.
#pragma once

#include <chrono>
#include <mutex>
#include <optional>
#include <string>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/convention_values.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/result.h"
#include "k40t_driver/session/accepted_request.h"

namespace k40t::operations {

class CaptureModeGuard {
 public:
  using Clock = std::chrono::steady_clock;
  static constexpr std::chrono::milliseconds kSettle{1500};  // 1.5 report periods

  // Every frame the driver writes and receives (any thread); `now`: when.
  void frame_sent(const protocol::FrameView& frame, const protocol::CodecOptions& codec);
  void frame_received(const protocol::FrameView& frame, const protocol::CodecOptions& codec,
                      Clock::time_point now = Clock::now());
  // ok, or why a request for `needed` would go unanswered. While the mode is unknown (no 0x000003
  // yet) nothing is refused.
  Status allows(protocol::CaptureMode needed, const char* request) const;
  // ok, or why a photo "stop" (0x000302 byte 2 = 1) would be refused: with photo mode 2 a
  // self-timer (photo_mode_2: self_timer) and the pod in that mode (0x000003), there is nothing to
  // stop: "stop" is valid in burst mode only (section 3.2.4.3). While the mode is unknown, ok.
  Status allows_stop(protocol::PhotoMode2 reading) const;
  // A request for `needed` that went unanswered (sent before any 0x000003 told the mode): the
  // pod's `no_ack` text and the likely reason, so that the user does not read a bare timeout.
  static std::string unanswered(protocol::CaptureMode needed, const char* request,
                                const std::string& no_ack);

 private:
  mutable std::mutex mutex_;
  std::optional<protocol::CaptureMode> mode_;
  std::optional<protocol::PhotoMode> photo_mode_;  // 0x000003's, the latest
  session::AcceptedRequest<protocol::CaptureModeRequest> switch_;
  std::optional<Clock::time_point> switched_at_;  // when the pod accepted the last switch
};

}  // namespace k40t::operations
