#include "k40t_driver/protocol/ack_order_setting.h"

#include "k40t_driver/protocol/ack_byte_order_evidence.h"

namespace k40t::protocol {

AckOrderSetting::AckOrderSetting(const CodecOptions& codec)
    : automatic_(codec.ack_byte_order_auto),
      state_(!codec.ack_byte_order_auto && codec.ack_byte_order == ByteOrder::kLittle ? kLittle
                                                                                      : 0u) {}

CodecOptions AckOrderSetting::codec_with(CodecOptions codec) const {
  const unsigned state = state_.load(std::memory_order_acquire);
  codec.ack_byte_order = order_of(state);
  codec.ack_byte_order_auto = automatic_ && (state & kLocked) == 0;
  return codec;
}

bool AckOrderSetting::observe(MessageId ack_id, const uint8_t* payload, size_t size) {
  if (!automatic_ || locked()) return false;
  AckOrderFit fit;
  fit_ack_byte_order(ack_id, payload, size, fit);
  if (!fit.tells()) return false;
  std::lock_guard<std::mutex> lock(evidence_mutex_);
  if (locked()) return false;  // another thread locked first
  evidence_ = fit.evidence;
  state_.store(kLocked | (fit.little ? kLittle : 0u), std::memory_order_release);
  return true;
}

std::string AckOrderSetting::evidence() const {
  std::lock_guard<std::mutex> lock(evidence_mutex_);
  return evidence_;
}

}  // namespace k40t::protocol
