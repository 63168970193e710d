#include "k40t_driver/ros/settings_sync.h"

#include <ros/console.h>

namespace k40t::driver {

SettingsSync::SettingsSync(ros::NodeHandle private_nh, PodDriver& driver)
    : driver_(driver), reader_(driver) {
  server_ = std::make_unique<dynamic_reconfigure::Server<Config>>(server_mutex_, private_nh);
  server_->setCallback([this](Config& config, uint32_t level) { on_reconfigure(config, level); });
}

void SettingsSync::on_reconfigure(Config& config, uint32_t) {
  if (!initialised_) {
    // The server's first call hands over its initial values: nothing to send, the pod's own
    // settings replace them on connect.
    initialised_ = true;
    current_ = config;
    return;
  }
  // A value dynamic_reconfigure only clamped is not sent beside a real change (the pod's value
  // stays); switching a setting off goes first (driver/setting_binding.h).
  for (const SettingBinding* binding : changes_to_send(setting_bindings(), config, current_)) {
    apply(*binding, config);
  }
  current_ = config;
}

session::AckResult SettingsSync::apply(const SettingBinding& binding, Config& next) {
  const session::AckResult result = binding.apply(driver_, next);
  std::lock_guard<std::mutex> lock(mutex_);
  if (result.ok()) {
    ++state_.changes_applied;
    state_.last_refusal.clear();
    binding.copy(current_, next);
    writes_.written(binding.name);
  } else {
    ++state_.changes_refused;
    state_.last_refusal = binding.name + ": " + result.message;
    ROS_WARN("K40T setting %s refused, reverted: %s", binding.name.c_str(), result.message.c_str());
    binding.copy(next, current_);  // what the server publishes after this callback
  }
  return result;
}

session::AckResult SettingsSync::write(const std::string& name,
                                       const std::function<void(Config&)>& edit) {
  const SettingBinding* binding = find_binding(name);
  if (!binding) return session::AckResult::not_sent("no setting named '" + name + "'");
  boost::recursive_mutex::scoped_lock server_lock(server_mutex_);
  Config next = current_;
  edit(next);
  const session::AckResult result = apply(*binding, next);
  if (result.ok()) server_->updateConfig(current_);
  return result;
}

SettingsState SettingsSync::read_from_pod() {
  std::lock_guard<std::mutex> one_read(read_mutex_);
  {
    boost::recursive_mutex::scoped_lock server_lock(server_mutex_);
    writes_.read_started();
  }
  const SettingsRead read = reader_.read();
  std::string message = read.message;
  {
    boost::recursive_mutex::scoped_lock server_lock(server_mutex_);
    Config config = current_;
    absorb(config, read.reports());
    writes_.keep_written(setting_bindings(), config, current_);
    current_ = config;
    server_->updateConfig(config);
    for (const SettingBinding* binding : writes_.to_resend(setting_bindings())) {
      const session::AckResult result = binding->apply(driver_, current_);
      if (!result.ok()) message += "; " + binding->name + " not restored: " + result.message;
    }
  }
  std::lock_guard<std::mutex> lock(mutex_);
  ++state_.reads;
  state_.read_ok = read.ok();
  state_.read_message = message;
  if (!state_.read_ok) ROS_WARN("K40T settings read-back incomplete: %s", message.c_str());
  return state_;
}

SettingsState SettingsSync::state() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return state_;
}

}  // namespace k40t::driver
