// The `conventions` diagnostic, ROS-free: every open reading of the document
// (docs/protocol/decisions.md#conventions), its value and where it came from; WARN, naming the
// reading and the frame or command, when the pod's traffic contradicts a value.
#pragma once

#include <vector>

#include "k40t_driver/driver/convention_tracker.h"
#include "k40t_driver/driver/pod_health.h"

namespace k40t::driver {

HealthCheck conventions_health(const std::vector<ConventionStatus>& readings);

}  // namespace k40t::driver
