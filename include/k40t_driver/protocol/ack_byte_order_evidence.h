// What one ACK's bytes say of ack_byte_order (docs/protocol/decisions.md#a2 and #conventions): the
// document does not say which byte order ACK fields use, but some fields read sensibly one way
// only: the response code (a code the document lists, section 3.3; 0x0000 reads the same both
// ways) and the ranged int16 fields of two settings read-backs: ACK 0x010100 (3.2.2.1: alarm
// thresholds -1000..5000 or -2732 "off", temperature difference 1..6000, reference -300..500,
// float 0..800, all 0.1 degC) and ACK 0x010502 (3.2.6.3: SBUS end points 0..2047).
// `k40t probe` and the driver's `conventions` diagnostic both use it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "k40t_driver/protocol/message_id.h"

namespace k40t::protocol {

struct AckOrderFit {
  bool big = true;     // every field looked at reads sensibly big-endian
  bool little = true;  // ... little-endian
  // The first bytes that read sensibly one way only, e.g. "ACK 0x010100 bytes 11-12: E8 03"; empty
  // when nothing could tell.
  std::string evidence;
  bool tells() const { return big != little; }
};

// `ack_id`: 0x01xxxx; `payload`: the ACK's payload (response code first). Folds into `fit`, so
// that several ACKs can be looked at together.
void fit_ack_byte_order(MessageId ack_id, const uint8_t* payload, size_t size, AckOrderFit& fit);

}  // namespace k40t::protocol
