// Shared machinery of the request handlers (src/sim/handlers_*.cpp): decode + validate a typed
// request, turn outcomes into ACK payloads, wrap model calls as table entries.
#pragma once

#include <string>
#include <utility>

#include "code_mapping.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/sim/request_handlers.h"

namespace k40t::sim::handlers {

// A decoded, validated request, or the response code that refuses it.
template <class Req>
struct Decoded {
  std::optional<Req> request;
  protocol::ResponseCode refusal = protocol::ResponseCode::kOk;
};

template <class Req>
Decoded<Req> decode(const protocol::FrameView& frame, const protocol::CodecOptions& codec) {
  Decoded<Req> out;
  if (frame.payload_size < Req::kMinSize) {
    out.refusal = protocol::ResponseCode::kLengthMismatch;
    return out;
  }
  Result<Req> decoded = protocol::decode_payload<Req>(frame, codec);
  if (!decoded || !decoded->validate()) {
    out.refusal = protocol::ResponseCode::kFailure;
    return out;
  }
  out.request = std::move(decoded).value();
  return out;
}

// A code-only ACK.
protocol::Payload code_ack(protocol::ResponseCode code, const protocol::CodecOptions& codec);
inline protocol::Payload outcome_ack(Outcome outcome, const protocol::CodecOptions& codec) {
  return code_ack(outcome_code(outcome), codec);
}

// A data ACK; if it does not encode (a model value outside the field), a failure code instead.
template <class Ack>
protocol::Payload data_ack(const Ack& ack, const protocol::CodecOptions& codec) {
  Result<protocol::Payload> encoded = protocol::encode_payload(ack, codec);
  if (!encoded) return code_ack(protocol::ResponseCode::kFailure, codec);
  return *encoded;
}

// A data ACK as a pod following one of the document's open readings sends it
// (protocol/convention_readings.h): `truth` must be valid, `played` (its bytes under the reading,
// which may lie outside the document's ranges, e.g. a zero-based zoom code) is what goes out.
template <class Ack>
protocol::Payload played_ack(const Ack& truth, const Ack& played,
                             const protocol::CodecOptions& codec) {
  if (!truth.validate()) return code_ack(protocol::ResponseCode::kFailure, codec);
  protocol::Payload payload;
  protocol::ByteWriter writer(payload.bytes.data(), payload.bytes.size());
  played.encode(writer, codec);
  payload.size = writer.size();
  return payload;
}

// Entry for a request whose ACK is the code only: `apply(pod, request)` returns the Outcome.
template <class Req, class Apply>
HandlerEntry plain(Apply apply) {
  return {Req::kId, [apply](RequestContext& ctx, const protocol::FrameView& frame) {
            const Decoded<Req> d = decode<Req>(frame, ctx.codec);
            if (!d.request) return code_ack(d.refusal, ctx.codec);
            return outcome_ack(apply(ctx.pod, *d.request), ctx.codec);
          }};
}

// Entry for a request with a data ACK: `answer(ctx, request)` returns the Req::Ack struct.
template <class Req, class Answer>
HandlerEntry with_data(Answer answer) {
  return {Req::kId, [answer](RequestContext& ctx, const protocol::FrameView& frame) {
            const Decoded<Req> d = decode<Req>(frame, ctx.codec);
            if (!d.request) return code_ack(d.refusal, ctx.codec);
            return data_ack(answer(ctx, *d.request), ctx.codec);
          }};
}

// A setting the model stores without rules: store it, answer OK.
template <class Req, class Store>
HandlerEntry store(Store store_fn) {
  return plain<Req>([store_fn](PodModel& pod, const Req& req) {
    store_fn(pod, req);
    return Outcome::kOk;
  });
}

// A setting the model only stores, field to field (codes pass through: same_code()):
// settings(pod).*field = request.*value.
template <class Req, class Settings, class Field, class Value>
HandlerEntry stored_setting(Settings& (*settings)(PodModel&), Field Settings::*field,
                            Value Req::*value) {
  return store<Req>([settings, field, value](PodModel& pod, const Req& req) {
    settings(pod).*field = same_code<Field>(req.*value);
  });
}

}  // namespace k40t::sim::handlers
