// Typed checks shared by the thermal and visible message tests: a struct against its
// hand-written golden frame, round trips, range errors and decode errors. The golden files are
// read with camera_golden.h's reader (the format is shared by every family).
#pragma once

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "camera_golden.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/parser.h"

namespace k40t::protocol::testing {

inline std::string golden_path(const std::string& file) {
  return std::string(K40T_TEST_DATA_DIR) + "/golden/" + file;
}

// A golden frame split by the protocol's own parser (header_excluded checksum, NOTES A1).
struct SplitFrame {
  bool ok = false;
  FrameHeader header;
  std::vector<uint8_t> payload;
};
inline SplitFrame split_frame(const GoldenFrame& golden) {
  SplitFrame split;
  int frames = 0;
  FrameParser parser(CrcCoverage::kHeaderExcluded);
  parser.feed(golden.bytes.data(), golden.bytes.size(), [&](const FrameView& view) {
    ++frames;
    split.header = view.header;
    split.payload.assign(view.payload, view.payload + view.payload_size);
  });
  split.ok = frames == 1 && parser.stats().bytes_discarded == 0;
  return split;
}

// The `occurrence`-th frame of `file` whose message id is T::kId.
template <class T>
SplitFrame golden_frame_of(const std::string& file, size_t occurrence = 0) {
  size_t seen = 0;
  for (const GoldenFrame& golden : load_golden(golden_path(file))) {
    SplitFrame split = split_frame(golden);
    EXPECT_TRUE(split.ok) << file << ":" << golden.line << ": not exactly one good frame";
    if (split.ok && split.header.message_id == T::kId && seen++ == occurrence) return split;
  }
  ADD_FAILURE() << file << " has no frame #" << occurrence << " of " << T::kName;
  return {};
}

// Decodes the golden frame as T (failing the test if it cannot).
template <class T>
T golden_message(const std::string& file, size_t occurrence = 0) {
  const SplitFrame split = golden_frame_of<T>(file, occurrence);
  auto decoded = decode_payload<T>(split.payload.data(), split.payload.size());
  EXPECT_TRUE(decoded) << decoded.error();
  return decoded ? decoded.value() : T{};
}

// `hand_built` holds the values the golden frame's comment spells out. Checks both directions:
// the golden payload decodes to exactly those fields, and encoding them gives the golden payload.
// Also checks the addresses of section 2.1.
template <class T>
void expect_matches_golden(const T& hand_built, const std::string& file, size_t occurrence = 0) {
  SCOPED_TRACE(std::string(T::kName) + " #" + std::to_string(occurrence));
  const SplitFrame split = golden_frame_of<T>(file, occurrence);
  ASSERT_TRUE(split.ok);

  const bool to_pod = T::kDirection == Direction::kHostToPod;
  EXPECT_EQ(split.header.source, to_pod ? kHostAddress : kCameraAddress);
  EXPECT_EQ(split.header.destination, to_pod ? kCameraAddress : kHostAddress);

  auto decoded = decode_payload<T>(split.payload.data(), split.payload.size());
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_TRUE(fields_match(record_fields(decoded.value()), record_fields(hand_built).values()));

  auto payload = encode_payload(hand_built);
  ASSERT_TRUE(payload) << payload.error();
  const std::vector<uint8_t> encoded(payload->data(), payload->data() + payload->size);
  if (encoded.size() == split.payload.size()) {
    EXPECT_EQ(encoded, split.payload);
  } else {
    // Golden frames that carry less than kSize (a refusal without its settings) only decode.
    EXPECT_LT(split.payload.size(), T::kSize);
  }
}

// encode -> decode gives back every field, and re-encoding gives the same bytes.
template <class T>
void expect_round_trip(const T& message) {
  SCOPED_TRACE(T::kName);
  auto first = encode_payload(message);
  ASSERT_TRUE(first) << first.error();
  EXPECT_EQ(first->size, T::kSize);
  auto decoded = decode_payload<T>(first->data(), first->size);
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_TRUE(fields_match(record_fields(decoded.value()), record_fields(message).values()));
  auto second = encode_payload(decoded.value());
  ASSERT_TRUE(second) << second.error();
  EXPECT_EQ(std::vector<uint8_t>(first->data(), first->data() + first->size),
            std::vector<uint8_t>(second->data(), second->data() + second->size));
}

// `valid` passes validation; after `mutate` it must be refused with a message naming `field`
// and the message, and nothing is encoded.
template <class T, class Mutate>
void expect_range_error(const T& valid, const char* field, Mutate mutate) {
  SCOPED_TRACE(std::string(T::kName) + "." + field);
  ASSERT_TRUE(valid.validate()) << valid.validate().message();
  T bad = valid;
  mutate(bad);
  auto encoded = encode_payload(bad);
  ASSERT_FALSE(encoded) << "accepted an out-of-range " << field;
  EXPECT_NE(encoded.error().find(std::string("'") + field + "'"), std::string::npos)
      << encoded.error();
  EXPECT_NE(encoded.error().find(T::kName), std::string::npos) << encoded.error();
}

// decode_payload of these bytes fails, and the message contains `needle`.
template <class T>
void expect_decode_error(const std::vector<uint8_t>& payload, const std::string& needle) {
  auto decoded = decode_payload<T>(payload.data(), payload.size());
  ASSERT_FALSE(decoded) << T::kName << " accepted a bad payload";
  EXPECT_NE(decoded.error().find(needle), std::string::npos) << decoded.error();
}

// The codes 0..255 for which the enum's to_string() has a name.
template <class E>
std::set<int> defined_codes() {
  std::set<int> codes;
  for (int code = 0; code <= 255; ++code) {
    if (to_string(static_cast<E>(code)) != nullptr) codes.insert(code);
  }
  return codes;
}

}  // namespace k40t::protocol::testing
