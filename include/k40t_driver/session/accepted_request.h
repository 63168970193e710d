// What the pod accepted of a request Req, seen from the frames going by (a driver's tx and rx
// frame handlers), whoever sent it: the last Req written, then its ACK. One request per id is
// outstanding at a time (docs/protocol/decisions.md#a5), so the ACK answers the last Req written.
// Not thread-safe: its owner locks.
#pragma once

#include <optional>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/ack.h"

namespace k40t::session {

template <class Req>
class AcceptedRequest {
 public:
  // A frame written: remembered if it is a Req.
  void sent(const protocol::FrameView& frame, const protocol::CodecOptions& codec) {
    if (frame.header.message_id != Req::kId) return;
    Result<Req> request = protocol::decode_payload<Req>(frame, codec);
    pending_ = request ? std::optional<Req>(request.value()) : std::nullopt;
  }
  // A frame received: the request the pod accepted when it is the ACK of the last Req with code
  // OK; nullopt for any other frame or code (a refusal leaves the pod as it was).
  std::optional<Req> accepted(const protocol::FrameView& frame,
                              const protocol::CodecOptions& codec) {
    if (frame.header.message_id != protocol::ack_id_of(Req::kId)) return std::nullopt;
    Result<protocol::PlainAck> ack = protocol::decode_payload<protocol::PlainAck>(frame, codec);
    std::optional<Req> request;
    request.swap(pending_);
    if (!ack || ack->code != protocol::ResponseCode::kOk) return std::nullopt;
    return request;
  }

 private:
  std::optional<Req> pending_;
};

}  // namespace k40t::session
