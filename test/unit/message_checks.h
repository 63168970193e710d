// gtest checks of typed message structs that need no golden frame: round trips, range errors
// on encode, decode errors, and the codes an enum names.
#pragma once

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <type_traits>
#include <vector>

#include "byte_checks.h"
#include "field_recorder.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/ack.h"

namespace k40t::testing {

// Each request answers with the plain ACK, not with an ACK struct of its own.
template <class... Requests>
inline constexpr bool acked_plainly = (std::is_same_v<typename Requests::Ack, protocol::PlainAck> &&
                                       ...);

template <class T>
Result<T> decode_bytes(const std::vector<uint8_t>& payload,
                       const protocol::CodecOptions& options = {}) {
  return protocol::decode_payload<T>(payload.data(), payload.size(), options);
}

// encode -> decode gives back every field (field_recorder.h's comparison), and re-encoding the
// decoded message gives the same bytes.
template <class T>
void expect_round_trip(const T& message, const protocol::CodecOptions& options = {}) {
  SCOPED_TRACE(T::kName);
  Result<protocol::Payload> first = protocol::encode_payload(message, options);
  ASSERT_TRUE(first) << first.error();
  EXPECT_EQ(first->size, T::kSize);
  Result<T> decoded = protocol::decode_payload<T>(first->data(), first->size, options);
  ASSERT_TRUE(decoded) << decoded.error();
  EXPECT_EQ(field_differences(record_fields(message), record_fields(decoded.value())), "");
  Result<protocol::Payload> second = protocol::encode_payload(decoded.value(), options);
  ASSERT_TRUE(second) << second.error();
  EXPECT_TRUE(same_bytes(std::vector<uint8_t>(second->data(), second->data() + second->size),
                         std::vector<uint8_t>(first->data(), first->data() + first->size)))
      << "re-encoding the decoded message";
}

// expect_round_trip of each message, all with the same options.
template <class... T>
void expect_round_trips(const protocol::CodecOptions& options, const T&... messages) {
  (expect_round_trip(messages, options), ...);
}

// encode_payload refuses `message`, naming `field` and the message in its error.
template <class T>
void expect_range_error(const T& message, const std::string& field) {
  Result<protocol::Payload> payload = protocol::encode_payload(message);
  ASSERT_FALSE(payload) << T::kName << ": " << field << " out of range was accepted";
  EXPECT_NE(payload.error().find("'" + field + "'"), std::string::npos) << payload.error();
  EXPECT_NE(payload.error().find(T::kName), std::string::npos) << payload.error();
}

// `valid` passes validation; after `mutate` it must be refused as above.
template <class T, class Mutate>
void expect_range_error(const T& valid, const char* field, Mutate mutate) {
  SCOPED_TRACE(std::string(T::kName) + "." + field);
  ASSERT_TRUE(valid.validate()) << valid.validate().message();
  T bad = valid;
  mutate(bad);
  expect_range_error(bad, field);
}

// decode_payload refuses `payload` with an error containing `words`.
template <class T>
void expect_decode_error(const std::vector<uint8_t>& payload, const std::string& words) {
  Result<T> decoded = decode_bytes<T>(payload);
  ASSERT_FALSE(decoded) << T::kName << " accepted a bad payload";
  EXPECT_NE(decoded.error().find(words), std::string::npos) << decoded.error();
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

}  // namespace k40t::testing
