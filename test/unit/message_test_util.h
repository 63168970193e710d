// Helpers for the typed message tests: golden frames by name, decoding a golden frame's payload
// into a struct, encoding a struct into a frame with a golden frame's header, round trips and
// validation failures.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <vector>

#include "field_recorder.h"
#include "golden_frames.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/ack.h"

namespace k40t::testing {

using test::GoldenFrame;

// The frames of test/data/golden/gimbal_laser_sbus.txt, read once with the shared reader.
inline const std::vector<GoldenFrame>& gimbal_laser_sbus_golden() {
  static const std::vector<GoldenFrame> frames = [] {
    auto read =
        test::read_golden_file(std::string(K40T_TEST_DATA_DIR) + "/golden/gimbal_laser_sbus.txt");
    EXPECT_TRUE(read) << read.error();
    return read ? read.value() : std::vector<GoldenFrame>{};
  }();
  return frames;
}

inline protocol::MessageId id_of(const GoldenFrame& g) {
  return g.bytes.size() < protocol::kHeaderSize ? 0
                                                : g.bytes[7] | g.bytes[8] << 8 | g.bytes[9] << 16;
}

// The `index`-th golden frame (0-based) of the message the catalogue calls `name`; fails the test
// if there is none.
inline const GoldenFrame& golden(const std::string& name, size_t index = 0) {
  static const GoldenFrame kEmpty;
  const protocol::MessageInfo* info = protocol::find_message(name);
  if (info == nullptr) {
    ADD_FAILURE() << "the catalogue has no message " << name;
    return kEmpty;
  }
  size_t seen = 0;
  for (const GoldenFrame& g : gimbal_laser_sbus_golden()) {
    if (id_of(g) == info->id && seen++ == index) return g;
  }
  ADD_FAILURE() << "no golden frame " << name << " #" << index;
  return kEmpty;
}

inline std::vector<uint8_t> payload_of(const GoldenFrame& g) {
  if (g.bytes.size() < protocol::kFrameOverhead) return {};
  return std::vector<uint8_t>(g.bytes.begin() + protocol::kHeaderSize,
                              g.bytes.end() - protocol::kChecksumSize);
}

template <class T>
Result<T> decode_bytes(const std::vector<uint8_t>& payload, const protocol::CodecOptions& o = {}) {
  return protocol::decode_payload<T>(payload.data(), payload.size(), o);
}

// Decodes the golden frame's payload as T (and checks the frame's id is T's).
template <class T>
T decode_golden(const GoldenFrame& g, const protocol::CodecOptions& o = {}) {
  EXPECT_GE(g.bytes.size(), protocol::kFrameOverhead) << g.where;
  if (g.bytes.size() < protocol::kFrameOverhead) return T{};
  const protocol::MessageId id = id_of(g);
  if constexpr (std::is_same_v<T, protocol::PlainAck>) {
    EXPECT_EQ(protocol::kind_of(id), protocol::MessageKind::kAck) << g.where;  // any 0x01xxxx
  } else {
    EXPECT_EQ(id, T::kId) << g.where;
  }
  Result<T> decoded = decode_bytes<T>(payload_of(g), o);
  EXPECT_TRUE(decoded) << g.where << ": " << decoded.error();
  return decoded ? decoded.value() : T{};
}

// Encodes `message` into a whole frame with the golden frame's addresses and sequence number.
template <class T>
std::vector<uint8_t> encode_like(const T& message, const GoldenFrame& g,
                                 const protocol::CodecOptions& o = {}) {
  if (g.bytes.size() < protocol::kFrameOverhead) return {};
  Result<protocol::Payload> payload = protocol::encode_payload(message, o);
  EXPECT_TRUE(payload) << payload.error();
  if (!payload) return {};
  EXPECT_EQ(payload->size, T::kSize);
  protocol::FrameHeader h;
  h.destination = {g.bytes[2], g.bytes[3]};
  h.sequence = g.bytes[4];
  h.source = {g.bytes[5], g.bytes[6]};
  h.message_id = T::kId;
  auto frame = protocol::encode_frame(h, payload->data(), payload->size,
                                      protocol::CrcCoverage::kHeaderExcluded);
  EXPECT_TRUE(frame) << frame.error();
  return frame ? std::vector<uint8_t>(frame->data(), frame->data() + frame->size())
               : std::vector<uint8_t>{};
}

template <class T>
void expect_encodes_to(const T& message, const GoldenFrame& g,
                       const protocol::CodecOptions& o = {}) {
  EXPECT_EQ(encode_like(message, g, o), g.bytes) << g.where;
}

// encode -> decode gives back every field.
template <class T>
void expect_round_trip(const T& message, const protocol::CodecOptions& o = {}) {
  SCOPED_TRACE(T::kName);
  Result<protocol::Payload> payload = protocol::encode_payload(message, o);
  ASSERT_TRUE(payload) << payload.error();
  EXPECT_EQ(payload->size, T::kSize);
  Result<T> back = protocol::decode_payload<T>(payload->data(), payload->size, o);
  ASSERT_TRUE(back) << back.error();
  EXPECT_EQ(field_differences(record_fields(message), record_fields(back.value())), "");
}

// encode_payload refuses `message`, naming `field` in its error.
template <class T>
void expect_range_error(const T& message, const std::string& field) {
  Result<protocol::Payload> payload = protocol::encode_payload(message);
  ASSERT_FALSE(payload) << T::kName << ": " << field << " out of range was accepted";
  EXPECT_NE(payload.error().find("'" + field + "'"), std::string::npos) << payload.error();
  EXPECT_NE(payload.error().find(T::kName), std::string::npos) << payload.error();
}

// decode_payload refuses `payload` with an error containing `words`.
template <class T>
void expect_decode_error(const std::vector<uint8_t>& payload, const std::string& words) {
  Result<T> decoded = decode_bytes<T>(payload);
  ASSERT_FALSE(decoded) << T::kName << " accepted a bad payload";
  EXPECT_NE(decoded.error().find(words), std::string::npos) << decoded.error();
}

}  // namespace k40t::testing
