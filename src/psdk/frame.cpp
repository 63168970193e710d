#include "k40t_driver/psdk/frame.h"

#include <cstring>
#include <string>

#include "k40t_driver/codec/enum_names.h"
#include "k40t_driver/psdk/aes.h"
#include "k40t_driver/psdk/crc.h"

namespace k40t::psdk {

const char* to_string(CommandSet set) {
  return consecutive_name(set, 1,
                          {"payload_state", "app_function", "data_push", "camera", "gimbal",
                           "osdk_function", "positioning"});
}

const char* to_string(PacketType type) {
  return consecutive_name(type, 0, {"command", "ack"});
}

const char* to_string(AckRequest request) {
  return consecutive_name(request, 0, {"no_ack", "ack_after_execution"});
}

const char* to_string(Encryption encryption) {
  return consecutive_name(encryption, 0, {"none", "aes"});
}

size_t frame_length_field(const uint8_t* f) {
  return static_cast<size_t>(f[1] | ((f[2] & 0x03) << 8));
}
uint8_t frame_version_field(const uint8_t* f) {
  return static_cast<uint8_t>(f[2] >> 2);
}

FrameHeader parse_header(const uint8_t* f) {
  FrameHeader h;
  h.ack_request = static_cast<AckRequest>(f[3] & 0x1F);
  h.packet_type = (f[3] & 0x20) ? PacketType::kAck : PacketType::kCommand;
  h.padding = static_cast<uint8_t>(f[4] & 0x1F);
  h.encryption = static_cast<Encryption>(f[4] >> 5);
  h.command = {f[6], f[7]};
  h.sequence = static_cast<uint16_t>(f[8] | (f[9] << 8));
  return h;
}

Result<EncodedFrame> encode_frame(const FrameHeader& header, const uint8_t* data, size_t size,
                                  const Aes128Ecb* cipher) {
  const auto fail = [](const std::string& why) { return Result<EncodedFrame>::fail(why); };
  const auto ack_request = static_cast<uint8_t>(header.ack_request);
  const auto encryption = static_cast<uint8_t>(header.encryption);
  if (ack_request > 0x1F)
    return fail("ACK request " + std::to_string(ack_request) + " does not fit in 5 bits");
  if (encryption > 0x07)
    return fail("encryption " + std::to_string(encryption) + " does not fit in 3 bits");
  if (header.encryption != Encryption::kNone && header.encryption != Encryption::kAes) {
    return fail("encryption type " + std::to_string(encryption) +
                " is not defined (0 none, 1 AES)");
  }
  const bool aes = header.encryption == Encryption::kAes;
  if (aes && cipher == nullptr)
    return fail("AES-encrypted frame requested but no AES key is configured");
  const size_t padding = aes ? (kAesBlockSize - size % kAesBlockSize) % kAesBlockSize : 0;
  if (size + padding > kMaxDataSize) {
    return fail("DATA of " + std::to_string(size) + " bytes" +
                (padding ? " (+" + std::to_string(padding) + " AES padding)" : std::string()) +
                " exceeds the maximum of 256 (frame length 16..272, docs/psdk.md#frames)");
  }

  EncodedFrame frame;
  uint8_t* b = frame.bytes_.data();
  const size_t data_size = size + padding;
  const size_t total = kFrameOverhead + data_size;
  b[0] = kSof;
  b[1] = static_cast<uint8_t>(total & 0xFF);
  b[2] = static_cast<uint8_t>(((total >> 8) & 0x03) | (kProtocolVersion << 2));
  b[3] = static_cast<uint8_t>(ack_request | (header.packet_type == PacketType::kAck ? 0x20 : 0x00));
  b[4] = static_cast<uint8_t>(padding | (encryption << 5));
  b[5] = 0;
  b[6] = header.command.set;
  b[7] = header.command.id;
  b[8] = static_cast<uint8_t>(header.sequence & 0xFF);
  b[9] = static_cast<uint8_t>(header.sequence >> 8);
  const uint16_t crc16_value = crc16(b, kHeaderCrcOffset);
  b[10] = static_cast<uint8_t>(crc16_value & 0xFF);
  b[11] = static_cast<uint8_t>(crc16_value >> 8);

  uint8_t* out = b + kHeaderSize;
  if (size > 0) std::memcpy(out, data, size);
  std::memset(out + size, 0, padding);  // zero fill (docs/psdk.md#frames)
  if (aes) {
    const Status encrypted = cipher->encrypt(out, data_size, out);
    if (!encrypted) return fail(encrypted.message());
  }
  const uint32_t crc32_value = crc32(b, kHeaderSize + data_size);
  uint8_t* tail = out + data_size;
  for (int i = 0; i < 4; ++i) tail[i] = static_cast<uint8_t>(crc32_value >> (8 * i));
  frame.size_ = total;
  return frame;
}

Result<Data> open_data(const FrameView& frame, const Aes128Ecb* cipher) {
  const FrameHeader& h = frame.header;
  if (h.padding > frame.data_size) {
    return Result<Data>::fail("padding of " + std::to_string(h.padding) +
                              " bytes is longer than DATA (" + std::to_string(frame.data_size) +
                              " bytes)");
  }
  if (frame.data_size > kMaxDataSize) return Result<Data>::fail("DATA longer than 256 bytes");
  Data out;
  switch (h.encryption) {
    case Encryption::kNone:
      if (frame.data_size > 0) std::memcpy(out.bytes.data(), frame.data, frame.data_size);
      break;
    case Encryption::kAes: {
      if (cipher == nullptr)
        return Result<Data>::fail("frame is AES-encrypted but no AES key is configured");
      const Status decrypted = cipher->decrypt(frame.data, frame.data_size, out.bytes.data());
      if (!decrypted) return Result<Data>::fail(decrypted.message());
      break;
    }
    default:
      return Result<Data>::fail("encryption type " +
                                std::to_string(static_cast<unsigned>(h.encryption)) +
                                " is not defined (0 none, 1 AES)");
  }
  out.size = frame.data_size - h.padding;
  return out;
}

}  // namespace k40t::psdk
