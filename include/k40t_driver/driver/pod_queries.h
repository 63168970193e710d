// Requests whose answers several parts of the glue need: the versions (get_versions service and
// the diagnostics' hardware id) and the pod's settings (dynamic_reconfigure read-back).
#pragma once

#include <optional>
#include <string>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::driver {

struct PodVersions {
  bool ok = false;
  std::string message;          // "ok", or which request failed and why
  std::string gimbal_hardware;  // "major.minor.patch"; empty when not read
  std::string gimbal_software;
  std::string camera;
  // "K40T gimbal hw 1.2.3 sw 1.2.4 camera 2.0.1" for diagnostics.
  std::string hardware_id() const;
};

// Reads 0x000018 and 0x000317 (blocking; both are tried even if the first fails).
PodVersions read_versions(PodDriver& driver);

struct PodSettings {
  std::optional<protocol::ThermalSettingsAck> thermal;  // 0x000100
  std::optional<protocol::VisibleSettingsAck> visible;  // 0x000200
  std::string error;                                    // why one of them is missing
};

// Reads 0x000100 and 0x000200 (blocking).
PodSettings read_settings(PodDriver& driver);

}  // namespace k40t::driver
