// One entry per pod setting (src/ros/settings_bindings.cpp): the dynamic_reconfigure parameters
// of cfg/K40t.cfg it covers, the request that sets them, the report that reads them back (or none:
// write-only), and the service that also writes it. The settings sync, the read-back, the docs
// table of docs/ros_interface.md ("Settings") and the tests are derived from this table; a unit
// test fails when a cfg parameter has no entry or an entry covers no cfg parameter.
#pragma once

#include <functional>
#include <string>
#include <tuple>
#include <vector>

#include "k40t_driver/K40tConfig.h"
#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/protocol/message_id.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::driver {

using Config = k40t_driver::K40tConfig;

// The reports a read-back gets (nullptr: not received). One of them carries each readable setting.
using SettingReports =
    std::tuple<const protocol::ThermalSettingsAck*, const protocol::VisibleSettingsAck*,
               const protocol::CameraSystemStatus*, const protocol::GimbalStatus*>;

// One parameter group and the request that sets it.
struct SettingBinding {
  std::string name;                 // e.g. "thermal_denoise"
  protocol::MessageId request = 0;  // the request that sets it, e.g. 0x00010D
  const char* request_name = "";    // its catalogue name, e.g. "thermal_set_denoise"
  std::function<bool(const Config&, const Config&)> differs;           // any of its fields changed
  std::function<void(Config& to, const Config& from)> copy;            // copy its fields
  std::function<session::AckResult(PodDriver&, const Config&)> apply;  // send the request
  // The change from `current` to `next` is only dynamic_reconfigure's clamping: each changed
  // field was outside the cfg range (as the pod reported it) and is now the nearest bound.
  std::function<bool(const Config& next, const Config& current)> only_clamped;
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

const std::vector<SettingBinding>& setting_bindings();
const SettingBinding* find_binding(const std::string& name);
// The binding a service writes (its `service` field), nullptr if none.
const SettingBinding* binding_for_service(const std::string& service);
// The cfg parameters a binding covers, in cfg order (found by what its copy() changes).
std::vector<std::string> parameters_of(const SettingBinding& binding);

// Read-back: the pod's reports -> the parameters they carry, for every binding read from them.
void absorb(Config& config, const SettingReports& reports);

// The table of docs/ros_interface.md ("Settings"), one row per binding (markdown).
std::string settings_table_markdown();

}  // namespace k40t::driver
