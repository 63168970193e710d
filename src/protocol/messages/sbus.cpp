#include "k40t_driver/protocol/messages/sbus.h"

#include "k40t_driver/protocol/catalogue.h"

namespace k40t::protocol {

void add_sbus_messages(std::vector<MessageInfo>&) {}

}  // namespace k40t::protocol
