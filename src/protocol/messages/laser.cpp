#include "k40t_driver/protocol/messages/laser.h"

#include "k40t_driver/protocol/catalogue.h"

namespace k40t::protocol {

void add_laser_messages(std::vector<MessageInfo>& out) {
  out.push_back(info_of<LaserRangeRequest>());
  out.push_back(info_of<LaserRangeAck>());
  out.push_back(info_of<LaserPeriodicRangeRequest>());
  out.push_back(info_of<LaserPeriodicRangeStatus>());
}

}  // namespace k40t::protocol
