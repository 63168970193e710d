// A message as a FrameView carrying it (only the id and the payload are filled), for the parts
// that watch frames go by: the driver's tx/rx frame handlers.
#pragma once

#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/ack.h"

namespace k40t::testing {

struct Framed {
  protocol::Payload payload;
  protocol::FrameView view;
  template <class Msg>
  explicit Framed(const Msg& message, protocol::MessageId id = Msg::kId,
                  const protocol::CodecOptions& codec = {}) {
    payload = protocol::encode_payload(message, codec).value();
    view.header.message_id = id;
    view.payload = payload.data();
    view.payload_size = payload.size;
  }
};

// The bare ACK of request `request_id` with `code`.
inline Framed plain_ack(protocol::MessageId request_id, protocol::ResponseCode code) {
  protocol::PlainAck ack;
  ack.code = code;
  return Framed(ack, protocol::ack_id_of(request_id));
}

}  // namespace k40t::testing
