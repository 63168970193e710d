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

}  // namespace k40t::protocol
