// Section 3.2.4.25 (0x000324), note: "当自己控制云台的时候，要下发关闭指令" - when you control the
// gimbal yourself, send the "off" command first; a tracker left on would steer the gimbal against
// the command. The driver watches whether the pod tracks (a 0x000324 it accepted, whoever sent
// it) and, before a request that drives the gimbal, switches tracking off; when the pod refuses
// that, the request is not sent and the caller is told why (PodDriver::request).
#pragma once

#include <mutex>
#include <type_traits>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/messages/camera_imaging.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/session/accepted_request.h"

namespace k40t::driver {

class BoxTrackingGuard {
 public:
  // Every frame written and received (any thread).
  void frame_sent(const protocol::FrameView& frame, const protocol::CodecOptions& codec);
  void frame_received(const protocol::FrameView& frame, const protocol::CodecOptions& codec);
  bool tracking() const;

 private:
  mutable std::mutex mutex_;
  session::AcceptedRequest<protocol::BoxTrackingRequest> switch_;
  bool tracking_ = false;  // until the pod accepts an "on"
};

// The 0x000324 that switches tracking off (the box is ignored then; sent as zeros).
protocol::BoxTrackingRequest box_tracking_off();

// Requests that drive the gimbal: 0x000012 (to an angle), 0x00002C (aim at a pixel), and 0x000010
// unless it only stops (a stop, such as the cmd_rate dead-man's, must go at once).
template <class Req>
bool drives_gimbal(const Req& request) {
  if constexpr (std::is_same_v<Req, protocol::GimbalControlRequest>) {
    return request.mode != protocol::GimbalMode::kNone ||
           request.yaw != protocol::GimbalYawDirection::kStop ||
           request.pitch != protocol::GimbalPitchDirection::kStop;
  }
  return std::is_same_v<Req, protocol::GimbalAngleRequest> ||
         std::is_same_v<Req, protocol::GimbalPointAtRequest>;
}

}  // namespace k40t::driver
