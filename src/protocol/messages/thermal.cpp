#include "k40t_driver/protocol/messages/thermal.h"

#include "k40t_driver/protocol/catalogue.h"

namespace k40t::protocol {

void add_thermal_messages(std::vector<MessageInfo>&) {}

}  // namespace k40t::protocol
