// 0x000002's attitude angles as a pod following one reading of their Euler order reports them
// (attitude_order, docs/protocol/decisions.md#conventions). The camera's true rotation is the
// joint chain's: yaw, then roll, then pitch (Z-X-Y), in the pod's terms (yaw right, pitch up, roll
// right-down positive). "zxy" reports those angles as they are; "zyx" reports the aerospace
// yaw-pitch-roll angles of the same rotation, which differ from them once the roll is not 0
// (7.6 deg apart at roll 10, pitch 45).
#pragma once

#include "k40t_driver/protocol/convention_values.h"
#include "k40t_driver/sim/geometry.h"

namespace k40t::sim {

YawPitchRoll attitude_in_order(const YawPitchRoll& chain_deg, protocol::AttitudeOrder order);

}  // namespace k40t::sim
