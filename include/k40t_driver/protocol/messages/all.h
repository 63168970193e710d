// Every message family of the pod protocol, and the list of all their message structs: the
// catalogue (catalogue.cpp) and the fuzz target register exactly these.
#pragma once

#include "k40t_driver/protocol/message_list.h"
#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/protocol/messages/sbus.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::protocol {

using PodMessages = JoinedMessages<GimbalMessages, ThermalMessages, VisibleMessages, CameraMessages,
                                   LaserMessages, SbusMessages>;

}  // namespace k40t::protocol
