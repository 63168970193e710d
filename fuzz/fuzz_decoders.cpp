// libFuzzer target: every decoder of the catalogue on arbitrary payloads.
//
// Input: bytes 0..2 pick the message id (24 bit, low byte first, as on the wire; an id the
// catalogue does not know picks entry id % catalogue size), the rest is the payload. The
// catalogue's describe() must refuse or decode it without crashing. For the message structs
// listed in kRoundTrips, whatever decodes and validates must survive encode_payload and decode
// back to the same fields, under both ACK byte orders.
#include <array>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../test/unit/field_recorder.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/messages/all.h"
#include "null_sink.h"

namespace {

using namespace k40t::protocol;  // NOLINT: a fuzz target names many message types
using k40t::Result;

// decode -> (validate) -> encode -> decode gives the same fields.
template <class T>
void round_trip(const uint8_t* payload, size_t size, const CodecOptions& options) {
  Result<T> decoded = decode_payload<T>(payload, size, options);
  if (!decoded || !decoded->validate()) return;  // what the pod says need not be sendable
  Result<Payload> encoded = encode_payload(decoded.value(), options);
  if (!encoded) {
    std::fprintf(stderr, "%s: validated but did not encode: %s\n", T::kName,
                 encoded.error().c_str());
    std::abort();
  }
  Result<T> again = decode_payload<T>(encoded->data(), encoded->size, options);
  if (!again) {
    std::fprintf(stderr, "%s: own encoding does not decode: %s\n", T::kName, again.error().c_str());
    std::abort();
  }
  const std::string diff = k40t::testing::field_differences(
      k40t::testing::record_fields(decoded.value()), k40t::testing::record_fields(again.value()));
  if (!diff.empty()) {
    std::fprintf(stderr, "%s: round trip changed fields:\n%s", T::kName, diff.c_str());
    std::abort();
  }
}

struct RoundTrip {
  MessageId id;
  void (*run)(const uint8_t*, size_t, const CodecOptions&);
};
// Every message struct of every family (messages/all.h) gets a typed round trip (ACKs without
// their own struct use PlainAck).
template <class... T>
constexpr std::array<RoundTrip, sizeof...(T)> round_trips(MessageList<T...>) {
  return {RoundTrip{T::kId, &round_trip<T>}...};
}
constexpr auto kRoundTrips = round_trips(PodMessages{});

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 3) return 0;
  const auto& all = catalogue();
  if (all.empty()) return 0;
  const MessageId wanted = data[0] | data[1] << 8 | data[2] << 16;
  const MessageInfo* info = find_message(wanted);
  if (info == nullptr) info = &all[wanted % all.size()];
  const uint8_t* payload = data + 3;
  const size_t payload_size = size - 3;

  CodecOptions big;
  CodecOptions little;
  little.ack_byte_order = ByteOrder::kLittle;
  for (const CodecOptions& options : {big, little}) {
    k40t::fuzz::NullSink sink;
    info->describe(payload, payload_size, options, sink);
    bool typed = false;
    for (const RoundTrip& r : kRoundTrips) {
      if (r.id == info->id) {
        r.run(payload, payload_size, options);
        typed = true;
      }
    }
    if (!typed && info->describe == &describe_payload<PlainAck>) {
      round_trip<PlainAck>(payload, payload_size, options);
    }
  }
  return 0;
}
