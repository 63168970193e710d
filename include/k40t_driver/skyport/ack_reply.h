// ACK DATA for the bridge's answers: a typed ACK encoded, or a return code alone; and a typed ACK
// that carries only a refusal code. Used by SkyportBridge's deferred answers.
#pragma once

#include <type_traits>

#include "k40t_driver/psdk/command.h"
#include "k40t_driver/psdk/frame.h"

namespace k40t::driver::skyport::detail {

template <class Ack>
psdk::Data reply_data(const Ack& ack) {
  if constexpr (std::is_same_v<Ack, psdk::AckCode>) {
    psdk::Data d;
    d.bytes[0] = static_cast<uint8_t>(ack);
    d.size = 1;
    return d;
  } else {
    const Result<psdk::Data> data = psdk::encode_data(ack);
    if (data) return data.value();
    return reply_data(psdk::AckCode::kError);  // our own reply is invalid: say so, do not lie
  }
}

template <class Ack>
Ack refused(psdk::AckCode code) {
  Ack ack;
  ack.code = code;
  return ack;
}

}  // namespace k40t::driver::skyport::detail
