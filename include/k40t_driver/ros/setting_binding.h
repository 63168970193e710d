// One entry per pod setting (src/ros/settings_bindings.cpp): the dynamic_reconfigure parameters
// of cfg/K40t.cfg it covers, the request that sets them, the report that reads them back (or none:
// write-only), and the service that also writes it. The settings sync, the read-back and the
// tests are derived from this table, and the "reconfigure" column of docs/protocol/*.md is checked
// against it; a unit test fails when a cfg parameter has no entry or an entry covers no cfg
// parameter.
#pragma once

#include <string>
#include <vector>

#include "k40t_driver/K40tConfig.h"
#include "k40t_driver/driver/setting_binding.h"

namespace k40t::driver {

using Config = k40t_driver::K40tConfig;

// The binding itself and the rule of which changes are sent are ROS-free
// (driver/setting_binding.h); the table is over dynamic_reconfigure's configuration.
using SettingBinding = BasicSettingBinding<Config>;

const std::vector<SettingBinding>& setting_bindings();
const SettingBinding* find_binding(const std::string& name);
// The binding a service writes (its `service` field), nullptr if none.
const SettingBinding* binding_for_service(const std::string& service);
// The cfg parameters a binding covers, in cfg order (found by what its copy() changes).
std::vector<std::string> parameters_of(const SettingBinding& binding);

// The one cfg parameter that is no setting: the last refusal and its reason, read-only (what a
// reconfigure request writes to it is replaced by the driver's value), so that `dynparam get` and
// rqt_reconfigure show why a change did not take. No binding covers it.
inline constexpr const char* kLastRefusalParameter = "last_refusal";

// Each of the parameters `names` whose value in `next` differs from `current` and lies outside its
// cfg range, as "palette 99 is outside 1..20" (joined by "; "); empty when there is none. Such a
// value is refused, not clamped (served_config.h).
std::string outside_cfg_range(const Config& next, const Config& current,
                              const std::vector<std::string>& names);

// Read-back: the pod's reports -> the parameters they carry, for every binding read from them.
void absorb(Config& config, const SettingReports& reports);

// The binding's cell in the "reconfigure" column of its request's row in docs/protocol/*.md: its
// cfg parameters, where it is read back from (or write-only) and the service that also writes it,
// e.g. "`palette`; read back from 0x010100; service `set_palette`".
std::string settings_docs_cell(const SettingBinding& binding);

}  // namespace k40t::driver
