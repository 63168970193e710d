// gtest checks against the golden frames (read by golden_file.h): finding a file's frames,
// splitting one with the protocol's own parser, decoding it as a typed message, encoding a
// message into a frame with a golden frame's header, and comparing fields (field_recorder.h).
// Every failure names the golden frame's file:line.
#pragma once

#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <vector>

#include "byte_checks.h"
#include "field_recorder.h"
#include "golden_file.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/parser.h"

namespace k40t::testing {

// The frames of test/data/golden/<file>; a file that cannot be read fails the test.
inline std::vector<GoldenFrame> load_golden(const std::string& file) {
  Result<std::vector<GoldenFrame>> read = read_golden_file(golden_path(file));
  EXPECT_TRUE(read) << "malformed golden file: " << read.error();
  return read ? read.value() : std::vector<GoldenFrame>{};
}

// ok: the bytes are exactly one frame with the document's header_excluded checksum
// (docs/protocol/decisions.md#a1) and nothing before or after it; otherwise `problem` says what the
// parser saw.
struct SplitFrame {
  bool ok = false;
  std::string problem;
  protocol::FrameHeader header;
  std::vector<uint8_t> payload;
};
inline SplitFrame split_frame(const GoldenFrame& golden) {
  SplitFrame split;
  int frames = 0;
  protocol::FrameParser parser(protocol::CrcCoverage::kHeaderExcluded);
  parser.feed(golden.bytes.data(), golden.bytes.size(), [&](const protocol::FrameView& view) {
    ++frames;
    split.header = view.header;
    split.payload.assign(view.payload, view.payload + view.payload_size);
  });
  split.ok = frames == 1 && parser.stats().bytes_discarded == 0 &&
             protocol::kFrameOverhead + split.payload.size() == golden.bytes.size();
  if (!split.ok) {
    split.problem = "the bytes are not exactly one frame with a good checksum and nothing else: " +
                    std::to_string(frames) + " frame(s), " +
                    std::to_string(parser.stats().checksum_errors) + " checksum error(s), " +
                    std::to_string(parser.stats().bytes_discarded) + " byte(s) discarded, " +
                    std::to_string(golden.bytes.size()) + " bytes";
  }
  return split;
}

// As split_frame, failing the test (naming the frame) unless the bytes are one good frame.
inline SplitFrame checked_split(const GoldenFrame& golden) {
  SplitFrame split = split_frame(golden);
  EXPECT_TRUE(split.ok) << golden.where() << ": " << split.problem;
  return split;
}

// The `index`-th frame (0-based) of `file` whose message id is `id`; fails the test if none.
inline GoldenFrame golden_with_id(const std::string& file, protocol::MessageId id,
                                  size_t index = 0) {
  size_t seen = 0;
  for (const GoldenFrame& golden : load_golden(file)) {
    const SplitFrame split = checked_split(golden);
    if (split.ok && split.header.message_id == id && seen++ == index) return golden;
  }
  ADD_FAILURE() << file << " has no frame #" << index << " of " << protocol::display_name(id);
  return {};
}

// The `index`-th frame of `file` of the message the catalogue calls `name`.
inline GoldenFrame golden(const std::string& file, const std::string& name, size_t index = 0) {
  const protocol::MessageInfo* info = protocol::find_message(name);
  if (info == nullptr) {
    ADD_FAILURE() << "the catalogue has no message " << name;
    return {};
  }
  return golden_with_id(file, info->id, index);
}

// The `index`-th frame of `file` of message T.
template <class T>
GoldenFrame golden_frame_of(const std::string& file, size_t index = 0) {
  return golden_with_id(file, T::kId, index);
}

// The frame's message id is T's (PlainAck stands for every plain 0x01xxxx ACK).
template <class T>
::testing::AssertionResult id_is_of(protocol::MessageId id) {
  const bool same = std::is_same_v<T, protocol::PlainAck>
                        ? protocol::kind_of(id) == protocol::MessageKind::kAck
                        : id == T::kId;
  if (same) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "the frame is " << protocol::display_name(id) << ", not " << T::kName;
}

// Decodes the golden frame's payload as T, failing the test (naming the frame) if the frame is
// not one good frame of T or does not decode.
template <class T>
T decode_golden(const GoldenFrame& golden, const protocol::CodecOptions& options = {}) {
  const SplitFrame split = checked_split(golden);
  if (!split.ok) return T{};
  EXPECT_TRUE(id_is_of<T>(split.header.message_id)) << golden.where();
  Result<T> decoded =
      protocol::decode_payload<T>(split.payload.data(), split.payload.size(), options);
  EXPECT_TRUE(decoded) << golden.where() << ": " << decoded.error();
  return decoded ? decoded.value() : T{};
}

template <class T>
T golden_message(const std::string& file, size_t index = 0) {
  return decode_golden<T>(golden_frame_of<T>(file, index));
}

// Encodes `message` into a whole frame with the golden frame's header (addresses, sequence,
// message id, which must be T's).
template <class T>
std::vector<uint8_t> encode_like(const T& message, const GoldenFrame& golden,
                                 const protocol::CodecOptions& options = {}) {
  const SplitFrame split = checked_split(golden);
  if (!split.ok) return {};
  EXPECT_TRUE(id_is_of<T>(split.header.message_id)) << golden.where();
  Result<protocol::Payload> payload = protocol::encode_payload(message, options);
  EXPECT_TRUE(payload) << golden.where() << ": " << payload.error();
  if (!payload) return {};
  EXPECT_EQ(payload->size, T::kSize) << golden.where();
  auto frame = protocol::encode_frame(split.header, payload->data(), payload->size,
                                      protocol::CrcCoverage::kHeaderExcluded);
  EXPECT_TRUE(frame) << golden.where() << ": " << frame.error();
  return frame ? std::vector<uint8_t>(frame->data(), frame->data() + frame->size())
               : std::vector<uint8_t>{};
}

// Encoding `message` gives the golden frame's bytes exactly.
template <class T>
void expect_encodes_to(const T& message, const GoldenFrame& golden,
                       const protocol::CodecOptions& options = {}) {
  EXPECT_TRUE(same_bytes(encode_like(message, golden, options), golden.bytes))
      << golden.where() << ": encoding " << T::kName << " differs from the hand-written bytes";
}

// THE field comparison for gtest: same fields in the same order with the same values; the
// failure lists each difference by field name, expected and actual value.
inline ::testing::AssertionResult fields_match(const FieldRecorder& actual,
                                               const FieldValues& expected) {
  const std::string differences = field_differences(expected, actual);
  if (differences.empty()) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "fields differ:\n" << differences;
}
inline ::testing::AssertionResult fields_match(const FieldRecorder& actual,
                                               const FieldRecorder& expected) {
  return fields_match(actual, expected.values());
}

// The golden frame decodes through the catalogue's type-erased decoder to its '=' line.
inline void expect_describes_to_expected(const GoldenFrame& golden,
                                         const protocol::CodecOptions& options = {}) {
  const SplitFrame split = checked_split(golden);
  if (!split.ok) return;
  const protocol::MessageInfo* info = protocol::find_message(split.header.message_id);
  ASSERT_NE(info, nullptr) << golden.where() << ": the catalogue does not know "
                           << protocol::display_name(split.header.message_id);
  FieldRecorder described;
  const Status status =
      info->describe(split.payload.data(), split.payload.size(), options, described);
  ASSERT_TRUE(status) << golden.where() << ": " << info->name << ": " << status.message();
  EXPECT_TRUE(fields_match(described, golden.expected)) << golden.where() << ": " << info->name;
}

// `hand_built` holds the values the golden frame's comment spells out. Checks both directions:
// the `index`-th golden frame of T in `file` decodes to exactly those fields and to its '='
// line, and encoding `hand_built` gives the golden payload. Also checks the addresses of section
// 2.1 (host <-> camera).
template <class T>
void expect_matches_golden(const T& hand_built, const std::string& file, size_t index = 0) {
  SCOPED_TRACE(std::string(T::kName) + " #" + std::to_string(index));
  const GoldenFrame golden = golden_frame_of<T>(file, index);
  const SplitFrame split = checked_split(golden);
  ASSERT_TRUE(split.ok);

  const bool to_pod = T::kDirection == protocol::Direction::kHostToPod;
  EXPECT_EQ(split.header.source, to_pod ? protocol::kHostAddress : protocol::kCameraAddress)
      << golden.where();
  EXPECT_EQ(split.header.destination, to_pod ? protocol::kCameraAddress : protocol::kHostAddress)
      << golden.where();

  const T decoded = decode_golden<T>(golden);
  EXPECT_TRUE(fields_match(record_fields(decoded), record_fields(hand_built))) << golden.where();
  EXPECT_TRUE(fields_match(record_fields(decoded), golden.expected)) << golden.where();

  auto payload = protocol::encode_payload(hand_built);
  ASSERT_TRUE(payload) << golden.where() << ": " << payload.error();
  const std::vector<uint8_t> encoded(payload->data(), payload->data() + payload->size);
  if (encoded.size() == split.payload.size()) {
    EXPECT_TRUE(same_bytes(encoded, split.payload)) << golden.where() << ": payload";
  } else {
    // Golden frames that carry less than kSize (a refusal without its settings) only decode.
    EXPECT_LT(split.payload.size(), T::kSize) << golden.where();
  }
}

}  // namespace k40t::testing
