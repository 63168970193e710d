// Whether the pod is measuring temperatures. Section 3.2.2.4 (0x000108): while measurement is on
// the pod sends the thermal report 0x000004 periodically, and while it is off it does not, so the
// diagnostics expect that report, and trust its alarm flags, only while it is on.
//
// Known from the pod's traffic alone, so that it holds whoever switched it (dynamic_reconfigure,
// `send`, a bag being replayed): the settings read-back 0x010100 (byte 4 bit 0) and a 0x000108
// the pod accepted (its ACK 0x010108 with code OK). Until either is seen: on, the document's
// default ("默认开启").
#pragma once

#include <mutex>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/session/accepted_request.h"

namespace k40t::driver {

class ThermalMeasurementWatch {
 public:
  // Every frame the driver writes, and every frame it receives (any thread).
  void frame_sent(const protocol::FrameView& frame, const protocol::CodecOptions& codec);
  void frame_received(const protocol::FrameView& frame, const protocol::CodecOptions& codec);
  bool measuring() const;

 private:
  mutable std::mutex mutex_;
  bool measuring_ = true;
  session::AcceptedRequest<protocol::ThermalMeasurementRequest> switch_;
};

}  // namespace k40t::driver
