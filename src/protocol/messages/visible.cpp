#include "k40t_driver/protocol/messages/visible.h"

#include "k40t_driver/protocol/catalogue.h"

namespace k40t::protocol {

void add_visible_messages(std::vector<MessageInfo>&) {}

}  // namespace k40t::protocol
