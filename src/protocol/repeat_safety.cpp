#include "k40t_driver/protocol/repeat_safety.h"

#include "k40t_driver/protocol/messages/camera_capture.h"

namespace k40t::protocol {

bool repeat_safe(MessageId id, const uint8_t* payload, size_t size) {
  switch (id) {
    case TakePhotoRequest::kId:
    case RecordRequest::kId:
    case PreciseReshootRequest::kId:
      return false;
    case ContinuousZoomRequest::kId: {
      // Byte 1 is the zoom command (section 3.2.4.6).
      if (size < 1) return true;
      const auto command = static_cast<ZoomCommand>(payload[0]);
      return command != ZoomCommand::kStepIn && command != ZoomCommand::kStepOut;
    }
    default:
      return true;
  }
}

}  // namespace k40t::protocol
