// Which settings were written, for the read-back of SettingsSync (ros/settings_sync.h), on any
// configuration type (driver/setting_binding.h):
//   - a setting written while a read-back was under way (a service called as soon as it exists)
//     was accepted by the pod after, or while, its value was read: what the read got of it may
//     predate the write, so the written value wins;
//   - a write-only setting (the pod cannot report it) that was written is sent again after each
//     read-back, so that a rebooted pod resumes it.
// Not thread-safe: the caller serialises it (SettingsSync holds its server mutex).
#pragma once

#include <set>
#include <string>
#include <vector>

#include "k40t_driver/driver/setting_binding.h"

namespace k40t::driver {

class SettingWrites {
 public:
  // A read-back begins: writes from now on are "during the read".
  void read_started() { during_read_.clear(); }
  // The pod accepted the binding `name`.
  void written(const std::string& name) {
    ever_.insert(name);
    during_read_.insert(name);
  }

  // `read` is the configuration a read-back produced, `written` the one holding what was last
  // accepted: each binding written since read_started() takes its fields from `written`.
  template <class Config>
  void keep_written(const std::vector<BasicSettingBinding<Config>>& table, Config& read,
                    const Config& written) const {
    for (const BasicSettingBinding<Config>& binding : table) {
      if (during_read_.count(binding.name) != 0) binding.copy(read, written);
    }
  }

  // The write-only bindings of `table` that were written: to send again after a read-back.
  template <class Config>
  std::vector<const BasicSettingBinding<Config>*> to_resend(
      const std::vector<BasicSettingBinding<Config>>& table) const {
    std::vector<const BasicSettingBinding<Config>*> out;
    for (const BasicSettingBinding<Config>& binding : table) {
      if (!binding.readable() && ever_.count(binding.name) != 0) out.push_back(&binding);
    }
    return out;
  }

 private:
  std::set<std::string> ever_;         // accepted at least once
  std::set<std::string> during_read_;  // accepted since the last read_started()
};

}  // namespace k40t::driver
