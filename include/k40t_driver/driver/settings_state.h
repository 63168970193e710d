// How the pod's settings stand against what the driver published: the settings sync
// (ros/settings_sync.h) keeps it, the diagnostics' "settings" check (pod_health.h) reads it.
#pragma once

#include <cstdint>
#include <string>

namespace k40t::driver {

struct SettingsState {
  bool read_ok = false;      // the last read-back got both settings ACKs
  std::string read_message;  // what the last read-back got, or why it failed
  uint64_t reads = 0;
  uint64_t changes_applied = 0;
  uint64_t changes_refused = 0;
  std::string last_refusal;  // "palette: <why>"; empty when the last change succeeded
};

}  // namespace k40t::driver
