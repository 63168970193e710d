#include "k40t_driver/protocol/messages/sbus.h"

#include <string>

namespace k40t::protocol {

// ---- 0x000500 -------------------------------------------------------------------------------
Status SbusRangeRequest::extra_checks() const {
  if (min_value >= max_value) {
    return Status::fail("field 'min_value' must be less than max_value (" +
                        std::to_string(max_value) + "), got " + std::to_string(min_value));
  }
  return Status::ok();
}

// ---- 0x010502 -------------------------------------------------------------------------------
Status SbusConfigAck::finish_decode(size_t payload_size) {
  if (payload_size <= kMinSize) {
    range.max_value = range.min_value = 0;
    channels = SbusChannelsRequest{0, 0, 0, 0, 0, 0, 0};
  }
  return Status::ok();
}

}  // namespace k40t::protocol
