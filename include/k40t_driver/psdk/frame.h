// The DJI PSDK v1 frame (protocol document section 2.1, docs/psdk.md#frames, docs/psdk.md):
//
//   offset size
//   0      1    SOF 0xAA
//   1      2    uint16 LE: bits 0-9 frame length (SOF..CRC32), bits 10-15 version (0)
//   3      1    bits 0-4 ACK request ("session": 0 no ACK, 1 ACK after execution),
//               bit 5 packet type (0 command, 1 ACK), bits 6-7 reserved
//   4      1    bits 0-4 padding length, bits 5-7 encryption (0 none, 1 AES)
//   5      1    reserved, 0
//   6      1    CMD SET
//   7      1    CMD ID
//   8      2    uint16 LE sequence (an ACK echoes its command's)
//   10     2    uint16 LE CRC16 over bytes 0..9
//   12     N    DATA (padding included)
//   12+N   4    uint32 LE CRC32 over bytes 0..11+N
//
// A frame is 16..272 bytes (DATA at most 256).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "k40t_driver/codec/result.h"

namespace k40t::psdk {

class Aes128Ecb;

constexpr uint8_t kSof = 0xAA;
constexpr uint8_t kProtocolVersion = 0;
constexpr size_t kHeaderSize = 12;
constexpr size_t kHeaderCrcOffset = 10;  // CRC16 covers bytes 0..9
constexpr size_t kCrc32Size = 4;
constexpr size_t kFrameOverhead = kHeaderSize + kCrc32Size;  // 16
constexpr size_t kMinFrameSize = kFrameOverhead;
constexpr size_t kMaxDataSize = 256;
constexpr size_t kMaxFrameSize = kFrameOverhead + kMaxDataSize;  // 272
constexpr size_t kAesBlockSize = 16;

// The command sets of section 2.4 (0x06 is named "OSDK function" in section 3.6).
enum class CommandSet : uint8_t {
  kPayloadState = 0x01,
  kAppFunction = 0x02,
  kDataPush = 0x03,
  kCamera = 0x04,
  kGimbal = 0x05,
  kOsdkFunction = 0x06,
  kPositioning = 0x07,
};
const char* to_string(CommandSet set);  // nullptr for sets the document does not define

enum class PacketType : uint8_t { kCommand = 0, kAck = 1 };
const char* to_string(PacketType type);

// Bits 0-4 of byte 3; values other than these two are carried through unchanged.
enum class AckRequest : uint8_t { kNoAck = 0, kAfterExecution = 1 };
const char* to_string(AckRequest request);

// Bits 5-7 of byte 4.
enum class Encryption : uint8_t { kNone = 0, kAes = 1 };
const char* to_string(Encryption encryption);

// Which command a frame is about: a command and its ACK share the key.
struct CommandKey {
  uint8_t set = 0;
  uint8_t id = 0;
  constexpr uint16_t packed() const { return static_cast<uint16_t>(set << 8 | id); }
  friend constexpr bool operator==(CommandKey a, CommandKey b) { return a.packed() == b.packed(); }
  friend constexpr bool operator!=(CommandKey a, CommandKey b) { return !(a == b); }
  friend constexpr bool operator<(CommandKey a, CommandKey b) { return a.packed() < b.packed(); }
};
constexpr CommandKey key_of(CommandSet set, uint8_t id) {
  return {static_cast<uint8_t>(set), id};
}

struct FrameHeader {
  AckRequest ack_request = AckRequest::kNoAck;
  PacketType packet_type = PacketType::kCommand;
  Encryption encryption = Encryption::kNone;
  uint8_t padding = 0;  // computed by encode_frame(); reported by the parser
  CommandKey command;
  uint16_t sequence = 0;
};

// DATA of at most 256 bytes in a fixed buffer (no heap).
struct Data {
  std::array<uint8_t, kMaxDataSize> bytes{};
  size_t size = 0;
  const uint8_t* data() const { return bytes.data(); }
};

// A frame as received; pointers are into the parser's buffer and valid only during the callback.
// `data` is DATA exactly as on the wire: ciphertext when encrypted, padding included. Use
// open_data() for the plain command data.
struct FrameView {
  FrameHeader header;
  const uint8_t* data = nullptr;
  size_t data_size = 0;
  const uint8_t* bytes = nullptr;  // SOF..CRC32
  size_t size = 0;
};

class EncodedFrame {
 public:
  const uint8_t* data() const { return bytes_.data(); }
  size_t size() const { return size_; }

 private:
  friend Result<EncodedFrame> encode_frame(const FrameHeader&, const uint8_t*, size_t,
                                           const Aes128Ecb*);
  std::array<uint8_t, kMaxFrameSize> bytes_{};
  size_t size_ = 0;
};

// Builds a frame around `data` (header.padding is ignored and computed). With header.encryption
// == kAes, DATA is zero-filled to a multiple of 16, the padding count goes in the header, and
// `cipher` encrypts it after the CRC16 and before the CRC32 (docs/psdk.md#frames). Fails, naming
// the problem, for DATA over 256 bytes (after padding), AES without a cipher, or an encryption or
// ACK-request value that does not fit its bits.
Result<EncodedFrame> encode_frame(const FrameHeader& header, const uint8_t* data, size_t size,
                                  const Aes128Ecb* cipher = nullptr);

// The plain command data of a received frame: decrypted if it is encrypted (which needs
// `cipher`), padding dropped. Fails, naming the problem, for an encrypted frame without a key,
// ciphertext that is not whole blocks, padding longer than DATA, or an unknown encryption type.
Result<Data> open_data(const FrameView& frame, const Aes128Ecb* cipher = nullptr);

// Header fields of a complete, already checked frame buffer (the parser's view of bytes 0..11).
FrameHeader parse_header(const uint8_t* frame);
size_t frame_length_field(const uint8_t* frame);    // bits 0-9 of bytes 1..2
uint8_t frame_version_field(const uint8_t* frame);  // bits 10-15 of bytes 1..2

}  // namespace k40t::psdk
