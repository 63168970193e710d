// The ACK byte order one link decodes and encodes ACKs with (docs/protocol/decisions.md#a2 and
// #conventions), changeable while the link runs: with `ack_byte_order: auto` it starts big (the
// default reading) and locks, for the rest of the run, onto the order the first ACK that reads
// sensibly one way only shows (protocol/ack_byte_order_evidence.h: a response code, the thermal or
// SBUS settings read-back). With big or little it never changes.
//
// One instance is shared by everything of a link that reads ack_byte_order (the Dispatcher's typed
// decoders, the RequestTracker's response codes, the Session's typed ACKs, the PodDriver's answer
// to 0x000310): each takes codec_with() at the moment it decodes or encodes.
// Thread-safe: observe() runs on the receive thread, order() and codec_with() on any thread.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <string>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/message_id.h"

namespace k40t::protocol {

class AckOrderSetting {
 public:
  // `codec.ack_byte_order` (the start) and `codec.ack_byte_order_auto`.
  explicit AckOrderSetting(const CodecOptions& codec);
  AckOrderSetting(const AckOrderSetting&) = delete;
  AckOrderSetting& operator=(const AckOrderSetting&) = delete;

  ByteOrder order() const { return order_of(state_.load(std::memory_order_acquire)); }
  bool automatic() const { return automatic_; }
  bool locked() const { return (state_.load(std::memory_order_acquire) & kLocked) != 0; }
  // `codec` with the order in force (ack_byte_order_auto cleared once locked).
  CodecOptions codec_with(CodecOptions codec) const;

  // Any ACK (0x01xxxx) as received, before anything decodes it. With auto, the first one whose
  // bytes tell the order locks it; true when this call locked. Later ACKs change nothing.
  bool observe(MessageId ack_id, const uint8_t* payload, size_t size);
  // The bytes that locked it, e.g. "ACK 0x010100 bytes 11-12: E8 03"; empty before.
  std::string evidence() const;

 private:
  // The order and whether it is locked in one atomic word, so that a reader sees both of one
  // moment (a locked order is never read with the order before it).
  static constexpr unsigned kLittle = 1;
  static constexpr unsigned kLocked = 2;
  static ByteOrder order_of(unsigned state) {
    return (state & kLittle) != 0 ? ByteOrder::kLittle : ByteOrder::kBig;
  }

  const bool automatic_;
  std::atomic<unsigned> state_;
  mutable std::mutex evidence_mutex_;  // evidence_; observe() locks under it
  std::string evidence_;
};

}  // namespace k40t::protocol
