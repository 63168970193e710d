#include "k40t_driver/protocol/messages/sbus.h"

#include <string>

#include "k40t_driver/protocol/catalogue.h"

namespace k40t::protocol {

// ---- 0x000500 -------------------------------------------------------------------------------
Status SbusRangeRequest::extra_checks() const {
  if (min_value >= max_value) {
    return Status::fail("field 'min_value' must be less than max_value (" +
                        std::to_string(max_value) + "), got " + std::to_string(min_value));
  }
  return Status::ok();
}

// ---- catalogue ------------------------------------------------------------------------------
void add_sbus_messages(std::vector<MessageInfo>& out) {
  out.push_back(info_of<SbusRangeRequest>());
  out.push_back(info_of<SbusChannelsRequest>());
  out.push_back(info_of<SbusConfigRequest>());
  out.push_back(info_of<SbusConfigAck>());
}

}  // namespace k40t::protocol
