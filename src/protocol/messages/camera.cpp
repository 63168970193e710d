#include "k40t_driver/protocol/messages/camera.h"

#include "k40t_driver/protocol/catalogue.h"

namespace k40t::protocol {

void add_camera_messages(std::vector<MessageInfo>&) {}

}  // namespace k40t::protocol
