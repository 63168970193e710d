#include "k40t_driver/driver/thermal_measurement_watch.h"

#include "k40t_driver/protocol/messages/thermal.h"

namespace k40t::driver {

namespace p = protocol;

void ThermalMeasurementWatch::frame_sent(const p::FrameView& frame, const p::CodecOptions& codec) {
  std::lock_guard<std::mutex> lock(mutex_);
  switch_.sent(frame, codec);
}

void ThermalMeasurementWatch::frame_received(const p::FrameView& frame,
                                             const p::CodecOptions& codec) {
  if (frame.header.message_id == p::ThermalSettingsAck::kId) {
    Result<p::ThermalSettingsAck> settings = p::decode_payload<p::ThermalSettingsAck>(frame, codec);
    if (!settings || settings->code != p::ResponseCode::kOk) return;
    std::lock_guard<std::mutex> lock(mutex_);
    measuring_ = settings->measurement_on;
    return;
  }
  std::lock_guard<std::mutex> lock(mutex_);
  if (const auto accepted = switch_.accepted(frame, codec)) measuring_ = accepted->measurement_on;
}

bool ThermalMeasurementWatch::measuring() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return measuring_;
}

}  // namespace k40t::driver
