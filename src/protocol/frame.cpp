#include "k40t_driver/protocol/frame.h"

#include <cstring>
#include <string>

#include "k40t_driver/protocol/crc.h"

namespace k40t::protocol {

uint16_t frame_checksum(const uint8_t* frame, size_t frame_size, CrcCoverage coverage) {
  const size_t covered_end = frame_size - kChecksumSize;
  const size_t start = coverage == CrcCoverage::kWholeFrame ? 0 : 1;
  return crc16(frame + start, covered_end - start);
}

Result<EncodedFrame> encode_frame(const FrameHeader& header, const uint8_t* payload,
                                  size_t payload_size, CrcCoverage coverage) {
  if (payload_size > kMaxPayloadSize) {
    return Result<EncodedFrame>::fail("payload of " + std::to_string(payload_size) +
                                      " bytes exceeds the frame maximum of 243 (section 2.1)");
  }
  if (header.message_id > kMaxMessageId) {
    return Result<EncodedFrame>::fail("message id " + std::to_string(header.message_id) +
                                      " does not fit in 24 bits (section 2.1)");
  }
  EncodedFrame frame;
  uint8_t* b = frame.bytes_.data();
  b[0] = kStx;
  b[1] = static_cast<uint8_t>(payload_size);
  b[2] = header.destination.system;
  b[3] = header.destination.component;
  b[4] = header.sequence;
  b[5] = header.source.system;
  b[6] = header.source.component;
  b[7] = static_cast<uint8_t>(header.message_id);
  b[8] = static_cast<uint8_t>(header.message_id >> 8);
  b[9] = static_cast<uint8_t>(header.message_id >> 16);
  if (payload_size > 0) std::memcpy(b + kHeaderSize, payload, payload_size);
  const size_t size = kFrameOverhead + payload_size;
  const CrcCoverage used = coverage == CrcCoverage::kAuto ? CrcCoverage::kHeaderExcluded : coverage;
  const uint16_t crc = frame_checksum(b, size, used);
  b[size - 2] = static_cast<uint8_t>(crc);
  b[size - 1] = static_cast<uint8_t>(crc >> 8);
  frame.size_ = size;
  return frame;
}

}  // namespace k40t::protocol
