// The K40T V1 frame (document section 2.1, docs/protocol/decisions.md#frame):
//   STX(0xFD) LEN DST_SYS DST_COMP SEQ SRC_SYS SRC_COMP MSGID[3, LE] PAYLOAD[LEN] CRC[2, LE]
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/message_id.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::protocol {

constexpr uint8_t kStx = 0xFD;
constexpr size_t kHeaderSize = 10;  // STX .. MSGID
constexpr size_t kChecksumSize = 2;
constexpr size_t kFrameOverhead = kHeaderSize + kChecksumSize;  // 12
// A frame is 12..255 bytes (docs/protocol/decisions.md#frame).
constexpr size_t kMaxPayloadSize = 243;
constexpr size_t kMaxFrameSize = kFrameOverhead + kMaxPayloadSize;

struct FrameHeader {
  Address destination;
  uint8_t sequence = 0;
  Address source;
  MessageId message_id = 0;
};

// A decoded frame; `payload` points into the parser's (or caller's) buffer and is valid only for
// the duration of the callback that receives it.
struct FrameView {
  FrameHeader header;
  const uint8_t* payload = nullptr;
  size_t payload_size = 0;
  const uint8_t* bytes = nullptr;  // the whole frame, STX to checksum
  size_t size = 0;
  CrcCoverage coverage = CrcCoverage::kHeaderExcluded;  // the coverage its checksum matched
};

// One encoded frame in a fixed buffer: no heap allocation.
class EncodedFrame {
 public:
  const uint8_t* data() const { return bytes_.data(); }
  size_t size() const { return size_; }

 private:
  friend Result<EncodedFrame> encode_frame(const FrameHeader&, const uint8_t*, size_t, CrcCoverage);
  std::array<uint8_t, kMaxFrameSize> bytes_{};
  size_t size_ = 0;
};

// Builds a frame around `payload`. kAuto is treated as kHeaderExcluded
// (docs/protocol/decisions.md#a1: send header_excluded until the parser has locked). Fails for a
// payload over 243 bytes or an id over 24 bits.
Result<EncodedFrame> encode_frame(const FrameHeader& header, const uint8_t* payload,
                                  size_t payload_size, CrcCoverage coverage);

// The checksum of a complete frame buffer (`frame_size` includes the two checksum bytes), for the
// given coverage (not kAuto).
uint16_t frame_checksum(const uint8_t* frame, size_t frame_size, CrcCoverage coverage);

}  // namespace k40t::protocol
