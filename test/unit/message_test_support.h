// Typed checks shared by the message-family tests: a struct against its hand-written golden
// frame, round trips, and range errors.
#pragma once

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "golden_frames.h"
#include "k40t_driver/protocol/message.h"

namespace k40t::test {

// The `occurrence`-th frame of `file` whose message id is T::kId, split into header and payload.
template <class T>
ParsedFrame golden_payload_of(const std::string& file, size_t occurrence = 0) {
  const GoldenFile golden = load_golden_file(file);
  ParsedFrame none;
  none.error = golden.error;
  if (!golden.error.empty()) return none;
  size_t seen = 0;
  for (const GoldenFrame& frame : golden.frames) {
    ParsedFrame parsed = parse_golden_frame(frame);
    if (!parsed.ok) return parsed;
    if (parsed.header.message_id == T::kId && seen++ == occurrence) return parsed;
  }
  none.error =
      std::string(file) + " has no frame #" + std::to_string(occurrence) + " of " + T::kName;
  return none;
}

// Decodes the golden frame as T (failing the test if it cannot).
template <class T>
T golden_message(const std::string& file, size_t occurrence = 0) {
  const ParsedFrame parsed = golden_payload_of<T>(file, occurrence);
  EXPECT_TRUE(parsed.ok) << parsed.error;
  auto decoded = protocol::decode_payload<T>(parsed.payload.data(), parsed.payload.size());
  EXPECT_TRUE(decoded) << decoded.error();
  return decoded ? decoded.value() : T{};
}

// `hand_built` holds the values the golden frame's comment spells out. Checks both directions:
// the golden payload decodes to exactly those fields, and encoding them (framed with the golden
// frame's header) gives the golden bytes. Also checks the addresses of section 2.1.
template <class T>
void expect_matches_golden(const T& hand_built, const std::string& file, size_t occurrence = 0) {
  SCOPED_TRACE(std::string(T::kName) + " #" + std::to_string(occurrence));
  const ParsedFrame parsed = golden_payload_of<T>(file, occurrence);
  ASSERT_TRUE(parsed.ok) << parsed.error;

  const bool to_pod = T::kDirection == protocol::Direction::kHostToPod;
  EXPECT_EQ(parsed.header.source, to_pod ? protocol::kHostAddress : protocol::kCameraAddress);
  EXPECT_EQ(parsed.header.destination, to_pod ? protocol::kCameraAddress : protocol::kHostAddress);

  auto decoded = protocol::decode_payload<T>(parsed.payload.data(), parsed.payload.size());
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_EQ(compare_fields(field_values(hand_built), field_values(decoded.value())), "");

  auto payload = protocol::encode_payload(hand_built);
  ASSERT_TRUE(payload) << payload.error();
  const std::vector<uint8_t> encoded(payload->data(), payload->data() + payload->size);
  if (encoded.size() == parsed.payload.size()) {
    EXPECT_EQ(encoded, parsed.payload);
  } else {
    // Golden frames that carry less than kSize (a refusal without its settings) only decode.
    EXPECT_LT(parsed.payload.size(), T::kSize);
  }
}

// encode -> decode gives back every field, and re-encoding gives the same bytes.
template <class T>
void expect_round_trip(const T& message) {
  SCOPED_TRACE(T::kName);
  auto first = protocol::encode_payload(message);
  ASSERT_TRUE(first) << first.error();
  EXPECT_EQ(first->size, T::kSize);
  auto decoded = protocol::decode_payload<T>(first->data(), first->size);
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_EQ(compare_fields(field_values(message), field_values(decoded.value())), "");
  auto second = protocol::encode_payload(decoded.value());
  ASSERT_TRUE(second) << second.error();
  EXPECT_EQ(std::vector<uint8_t>(first->data(), first->data() + first->size),
            std::vector<uint8_t>(second->data(), second->data() + second->size));
}

// `valid` passes validation; after `mutate` it must be refused with a message naming `field`.
template <class T, class Mutate>
void expect_range_error(const T& valid, const char* field, Mutate mutate) {
  SCOPED_TRACE(std::string(T::kName) + "." + field);
  ASSERT_TRUE(valid.validate()) << valid.validate().message();
  T bad = valid;
  mutate(bad);
  auto encoded = protocol::encode_payload(bad);
  ASSERT_FALSE(encoded) << "accepted an out-of-range " << field;
  EXPECT_NE(encoded.error().find(std::string("'") + field + "'"), std::string::npos)
      << encoded.error();
  EXPECT_NE(encoded.error().find(T::kName), std::string::npos) << encoded.error();
}

// decode_payload of these bytes fails, and the message contains `needle`.
template <class T>
void expect_decode_error(const std::vector<uint8_t>& payload, const std::string& needle) {
  auto decoded = protocol::decode_payload<T>(payload.data(), payload.size());
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

}  // namespace k40t::test
