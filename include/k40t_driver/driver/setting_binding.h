// One pod setting as the driver sends and reads it back, for any configuration type: the ROS glue
// instantiates it with dynamic_reconfigure's K40tConfig (ros/setting_binding.h holds the table),
// the unit tests with a small struct of their own. changes_to_send() is the rule that decides
// which settings a reconfigure sends, and in which order.
#pragma once

#include <algorithm>
#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/protocol/message_id.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::driver {

// The reports a read-back gets (nullptr: not received). One of them carries each readable setting.
using SettingReports =
    std::tuple<const protocol::ThermalSettingsAck*, const protocol::VisibleSettingsAck*,
               const protocol::CameraSystemStatus*, const protocol::GimbalStatus*>;

// One parameter group and the request that sets it.
template <class Config>
struct BasicSettingBinding {
  std::string name;                 // e.g. "thermal_denoise"
  protocol::MessageId request = 0;  // the request that sets it, e.g. 0x00010D
  const char* request_name = "";    // its catalogue name, e.g. "thermal_set_denoise"
  std::function<bool(const Config&, const Config&)> differs;           // any of its fields changed
  std::function<void(Config& to, const Config& from)> copy;            // copy its fields
  std::function<session::AckResult(PodDriver&, const Config&)> apply;  // send the request
  // The change switches this setting off: sent before the others, so that one of two settings the
  // pod will not have on together (strong light, backlight) is off before the other goes on.
  std::function<bool(const Config& next, const Config& current)> switches_off;
  // The report that carries it (0x010100, 0x010200, 0x000003 or 0x000001) and how its fields are
  // read from it. 0: the pod cannot report it (write-only); a value set through reconfigure is
  // sent again after each read-back, so that a rebooted pod resumes it.
  protocol::MessageId read_from = 0;
  std::function<void(Config&, const SettingReports&)> read_back;
  std::string service;  // the service that also writes it through SettingsSync::write(), or ""

  bool readable() const { return read_from != 0; }
};

// The bindings of `table` a change from `current` to `next` sends, in the order to send them:
// those that switch their setting off first (3.2.3.9/3.2.3.10 note), table order otherwise.
// Nothing is clamped before (ros/served_config.h): every changed value is the one asked for.
template <class Config>
std::vector<const BasicSettingBinding<Config>*> changes_to_send(
    const std::vector<BasicSettingBinding<Config>>& table, const Config& next,
    const Config& current) {
  std::vector<const BasicSettingBinding<Config>*> changed;
  for (const BasicSettingBinding<Config>& binding : table) {
    if (binding.differs(next, current)) changed.push_back(&binding);
  }
  std::stable_partition(changed.begin(), changed.end(), [&](const auto* binding) {
    return binding->switches_off && binding->switches_off(next, current);
  });
  return changed;
}

}  // namespace k40t::driver
