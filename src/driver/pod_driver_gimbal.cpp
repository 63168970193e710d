// PodDriver's gimbal duties: the cmd_rate commander's output and what else changes the dial speed
// it relies on, and box tracking switched off before the gimbal is driven
// (driver/box_tracking_guard.h). Split from pod_driver.cpp, which keeps the link's duties.
#include <mutex>
#include <string>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/protocol/messages/gimbal.h"

namespace k40t::driver {

using protocol::FrameView;
using session::AckResult;

void PodDriver::command_rate(double pitch_deg_s, double yaw_deg_s) {
  RateCommander::Output output;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    output = rate_.command(pitch_deg_s, yaw_deg_s, SteadyClock::now());
  }
  wake_.notify_all();  // the dead-man deadline moved
  send_rate_output(output);
}

void PodDriver::send_rate_output(const RateCommander::Output& output) {
  // Failures show in the session's counters; a dial speed that did not take is sent again.
  if (output.speed) {
    request_async(*output.speed, [this](const AckResult& result) {
      if (result.ok()) return;
      std::lock_guard<std::mutex> lock(mutex_);
      rate_.forget_speed();
    });
  }
  if (output.control) request_async(*output.control, [](const AckResult&) {});
}

namespace {
std::string box_tracking_refused(const AckResult& off) {
  return "not sent: box tracking is on and the pod refused to switch it off first (section "
         "3.2.4.25: off while the gimbal is controlled): " +
         off.message;
}
}  // namespace

Status PodDriver::box_tracking_off_first() {
  if (!box_tracking_.tracking()) return Status::ok();
  const AckResult off = session_->request(box_tracking_off());
  return off.ok() ? Status::ok() : Status::fail(box_tracking_refused(off));
}

void PodDriver::box_tracking_off_then(protocol::MessageId id, const protocol::Payload& payload,
                                      std::function<void(const AckResult&)> done) {
  Result<protocol::Payload> off = protocol::encode_payload(box_tracking_off(), codec());
  session_->request_async(protocol::BoxTrackingRequest::kId, off.value(),
                          [this, id, payload, done = std::move(done)](const AckResult& result) {
                            if (!result.ok())
                              return done(AckResult::not_sent(box_tracking_refused(result)));
                            session_->request_async(id, payload, done);
                          });
}

// Whoever sets the dial speed (reconfigure, `send`) or restarts the gimbal changes the speed the
// rate commands turn at: the commander must not believe its last 0x000017 still holds.
void PodDriver::track_dial_speed(const FrameView& frame) {
  const protocol::MessageId id = frame.header.message_id;
  if (id != protocol::GimbalDialSpeedRequest::kId && id != protocol::GimbalRestartRequest::kId)
    return;
  Result<protocol::GimbalDialSpeedRequest> speed =
      protocol::decode_payload<protocol::GimbalDialSpeedRequest>(frame, codec());
  std::lock_guard<std::mutex> lock(mutex_);
  if (id == protocol::GimbalDialSpeedRequest::kId && speed)
    rate_.speed_sent(speed.value());
  else
    rate_.forget_speed();
}

}  // namespace k40t::driver
