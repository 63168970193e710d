// sbus messages — see the family comment at the top once written.
#pragma once

#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/messages/ack.h"

namespace k40t::protocol {}  // namespace k40t::protocol
