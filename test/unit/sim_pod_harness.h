// Drives the simulator's request handlers and reports without a link: typed requests in (encoded
// by the protocol library), ACK codes and typed reports out, model time advanced by hand.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <optional>
#include <vector>

#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/sim/pod_model.h"
#include "k40t_driver/sim/pod_reports.h"
#include "k40t_driver/sim/request_handlers.h"
#include "request_with.h"

namespace k40t::sim::testing {

using k40t::testing::request_with;
using protocol::ResponseCode;

class PodHarness {
 public:
  explicit PodHarness(const PodConfig& config = {}, protocol::CodecOptions codec = {})
      : pod(config), codec(codec) {}

  // The ACK payload for raw request bytes, or nullopt when the pod stays silent.
  std::optional<protocol::Payload> raw(protocol::MessageId id,
                                       const std::vector<uint8_t>& payload) {
    protocol::FrameView frame;
    frame.header.message_id = id;
    frame.header.source = protocol::kHostAddress;
    frame.header.destination = protocol::kCameraAddress;
    frame.payload = payload.data();
    frame.payload_size = payload.size();
    return answer_request(pod, codec, frame);
  }

  template <class Req>
  std::optional<protocol::Payload> ack_of(const Req& request) {
    Result<protocol::Payload> encoded = protocol::encode_payload(request, codec);
    EXPECT_TRUE(encoded) << encoded.error();
    if (!encoded) return std::nullopt;
    return raw(Req::kId, std::vector<uint8_t>(encoded->data(), encoded->data() + encoded->size));
  }

  // The response code of the ACK (kTimeout when there was no ACK at all).
  template <class Req>
  protocol::ResponseCode send(const Req& request) {
    const auto ack = ack_of(request);
    if (!ack) return protocol::ResponseCode::kTimeout;
    return protocol::ack_response_code(ack->data(), ack->size, codec);
  }

  // The typed data ACK.
  template <class Req>
  typename Req::Ack ask(const Req& request) {
    const auto ack = ack_of(request);
    EXPECT_TRUE(ack.has_value()) << Req::kName << ": no ACK";
    if (!ack) return {};
    auto decoded = protocol::decode_payload<typename Req::Ack>(ack->data(), ack->size, codec);
    EXPECT_TRUE(decoded) << decoded.error();
    return decoded ? *decoded : typename Req::Ack{};
  }

  // Advances the model; keeps its events.
  void run(double seconds, double dt = 0.01) {
    const int steps = static_cast<int>(std::lround(seconds / dt));
    for (int i = 0; i < steps; ++i) {
      pod.step(dt);
      for (PodEvent& e : pod.take_events()) events.push_back(e);
    }
  }

  // The periodic report `Msg` as the pod would send it now.
  template <class Msg>
  Msg report() {
    for (const PeriodicReport& r : periodic_reports()) {
      if (r.id != Msg::kId) continue;
      auto payload = r.encode(pod, codec);
      EXPECT_TRUE(payload) << payload.error();
      if (!payload) return {};
      auto decoded = protocol::decode_payload<Msg>(payload->data(), payload->size, codec);
      EXPECT_TRUE(decoded) << decoded.error();
      return decoded ? *decoded : Msg{};
    }
    ADD_FAILURE() << Msg::kName << " is not a periodic report";
    return {};
  }

  // The status frames `Msg` among the events so far.
  template <class Msg>
  std::vector<Msg> status_frames() const {
    std::vector<Msg> out;
    for (const PodEvent& e : events) {
      const auto message = encode_event(e, codec);
      if (!message || message->id != Msg::kId) continue;
      auto decoded =
          protocol::decode_payload<Msg>(message->payload.data(), message->payload.size, codec);
      EXPECT_TRUE(decoded) << decoded.error();
      if (decoded) out.push_back(*decoded);
    }
    return out;
  }

  PodModel pod;
  protocol::CodecOptions codec;
  EventQueue events;
};

// The tests that drive one default pod, `h`; a suite names it by an alias:
//   using SimFocus = SimPodTest;  TEST_F(SimFocus, ...) { h.send(...); }
class SimPodTest : public ::testing::Test {
 protected:
  PodHarness h;
};

}  // namespace k40t::sim::testing
