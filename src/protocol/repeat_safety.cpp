#include "k40t_driver/protocol/repeat_safety.h"

#include "k40t_driver/protocol/messages/camera_capture.h"
#include "k40t_driver/protocol/messages/gimbal.h"

namespace k40t::protocol {

bool repeat_safe(MessageId id, const uint8_t* payload, size_t size) {
  switch (id) {
    case TakePhotoRequest::kId:
    case RecordRequest::kId:
    case PreciseReshootRequest::kId:
    case GimbalDriftCalibrationRequest::kId:
    case GimbalLinearCalibrationRequest::kId:
    case GimbalAccelerationCalibrationRequest::kId:
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

std::chrono::milliseconds done_ack_wait(MessageId id, const Conventions& conventions) {
  const bool calibration = id == GimbalDriftCalibrationRequest::kId ||
                           id == GimbalLinearCalibrationRequest::kId ||
                           id == GimbalAccelerationCalibrationRequest::kId;
  if (!calibration || conventions.calibration_end == CalibrationEnd::kStatus)
    return std::chrono::milliseconds::zero();
  return kCalibrationAckWait;
}

}  // namespace k40t::protocol
