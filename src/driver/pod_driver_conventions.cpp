// The PodDriver's part in the open readings (docs/protocol/decisions.md#conventions): what it
// shows the ConventionTracker of the frames it sends and receives.
#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/protocol/message_id.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/gimbal.h"

namespace k40t::driver {

using protocol::FrameView;

void PodDriver::observe_sent(const FrameView& frame) {
  if (frame.header.message_id == protocol::GimbalControlRequest::kId) {
    if (auto command = protocol::decode_payload<protocol::GimbalControlRequest>(frame, codec()))
      conventions_.observe_command(*command, ConventionTracker::ConventionTracker::steady_now_s());
  } else if (frame.header.message_id == protocol::GimbalAngleRequest::kId) {
    if (auto command = protocol::decode_payload<protocol::GimbalAngleRequest>(frame, codec()))
      conventions_.observe_command(*command, ConventionTracker::ConventionTracker::steady_now_s());
  }
}

void PodDriver::observe_received(const FrameView& frame) {
  const protocol::MessageId id = frame.header.message_id;
  if (protocol::kind_of(id) == protocol::MessageKind::kAck)
    conventions_.observe_ack(id, frame.payload, frame.payload_size, *ack_order_);
  const bool calibration_ack =
      id == protocol::ack_id_of(protocol::GimbalDriftCalibrationRequest::kId) ||
      id == protocol::ack_id_of(protocol::GimbalLinearCalibrationRequest::kId) ||
      id == protocol::ack_id_of(protocol::GimbalAccelerationCalibrationRequest::kId);
  if (calibration_ack && protocol::ack_response_code(frame.payload, frame.payload_size, codec()) ==
                             protocol::ResponseCode::kOk)
    conventions_.observe_calibration_acked(ConventionTracker::ConventionTracker::steady_now_s());
}

std::vector<ConventionStatus> PodDriver::conventions_report() {
  conventions_.observe_crc_coverage(stats().crc_coverage);
  return conventions_.report();
}

}  // namespace k40t::driver
