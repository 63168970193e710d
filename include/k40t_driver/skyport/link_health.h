// The SKYPORT bridge's health in one line, for its diagnostics (docs/skyport.md), ROS-free: the
// first of these that holds, most serious first.
//   ERROR  the link is not connected; no frame from the adapter for `silence_timeout_s` (or none
//          yet); every identity verification refused;
//   WARN   no identity verification yet; the aircraft announces power-off; the pod's state is
//          stale (nothing from the pod for `pod_stale_s`, or nothing yet);
//   OK     otherwise.
#pragma once

#include <string>

#include "k40t_driver/skyport/skyport_bridge.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::driver::skyport {

enum class HealthLevel { kOk, kWarn, kError };

struct LinkHealthInput {
  transport::LinkState link = transport::LinkState::kClosed;
  double silent_s = -1;  // since the adapter's last frame; negative: none yet
  double silence_timeout_s = 1.0;
  BridgeStats bridge;
  double pod_age_s = -1;  // PodSnapshot::state_age_s
  double pod_stale_s = 3.0;
};

struct LinkHealth {
  HealthLevel level = HealthLevel::kOk;
  std::string summary;
  bool pod_stale = false;  // reported on its own too, whatever the summary
};

LinkHealth link_health(const LinkHealthInput& in);

}  // namespace k40t::driver::skyport
