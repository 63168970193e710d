// A rule the thermal and visible settings ACKs share (src only: not part of the API).
#pragma once

#include <cstddef>

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::protocol::detail {

// The "read all settings" ACKs (0x010100, 0x010200) carry either the 2-byte response code alone
// (a refusal) or the code and at least `settings_size` bytes: their finish_decode(). Fails naming
// the byte counts.
Status settings_follow(size_t payload_size, ResponseCode code, size_t settings_size);

}  // namespace k40t::protocol::detail
