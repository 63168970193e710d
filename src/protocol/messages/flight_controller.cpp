#include "k40t_driver/protocol/messages/flight_controller.h"

namespace k40t::protocol {

CameraGpsAck CameraGpsAck::answering(const CameraGpsRequest& request) {
  CameraGpsAck ack;
  ack.hour = request.hour;
  ack.minute = request.minute;
  ack.second = request.second;
  ack.millisecond = request.millisecond;
  return ack;
}

}  // namespace k40t::protocol
