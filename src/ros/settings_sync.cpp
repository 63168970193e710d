#include "k40t_driver/ros/settings_sync.h"

#include <ros/console.h>

namespace k40t::driver {

namespace {

std::map<std::string, std::vector<std::string>> parameters_of_bindings() {
  std::map<std::string, std::vector<std::string>> parameters;
  for (const SettingBinding& binding : setting_bindings()) {
    parameters[binding.name] = parameters_of(binding);
  }
  return parameters;
}

}  // namespace

SettingsSync::SettingsSync(ros::NodeHandle private_nh, PodDriver& driver)
    : driver_(driver), reader_(driver), parameters_(parameters_of_bindings()), mirror_(private_nh) {
  server_ = std::make_unique<dynamic_reconfigure::Server<ServedConfig>>(server_mutex_, private_nh);
  server_->setCallback(
      [this](ServedConfig& config, uint32_t level) { on_reconfigure(config, level); });
}

void SettingsSync::on_reconfigure(Config& config, uint32_t) {
  if (!initialised_) {
    // The server's first call hands over its initial values: nothing to send, the pod's own
    // settings replace them on connect. A refusal of an earlier run is not this one's.
    initialised_ = true;
    config.last_refusal.clear();
    current_ = config;
    mirror_.publish(current_);
    return;
  }
  // Switching a setting off goes first (driver/setting_binding.h).
  std::string refusals;
  const auto to_send = changes_to_send(setting_bindings(), config, current_);
  for (const SettingBinding* binding : to_send) apply(*binding, config, refusals);
  if (!to_send.empty()) end_write(refusals);
  config.last_refusal = current_.last_refusal;  // read-only: what the server publishes is ours
  current_ = config;
  mirror_.publish(current_);
}

session::AckResult SettingsSync::apply(const SettingBinding& binding, Config& next,
                                       std::string& refusals) {
  const std::string outside = outside_cfg_range(next, current_, parameters_.at(binding.name));
  const session::AckResult result =
      outside.empty() ? binding.apply(driver_, next) : session::AckResult::not_sent(outside);
  if (result.ok()) {
    binding.copy(current_, next);
    writes_.written(binding.name);
  } else {
    const std::string refusal = binding.name + ": " + result.message;
    refusals += (refusals.empty() ? "" : "; ") + refusal;
    ROS_ERROR("K40T setting refused, the pod's value stays: %s", refusal.c_str());
    binding.copy(next, current_);  // what the server publishes after this callback
  }
  std::lock_guard<std::mutex> lock(mutex_);
  ++(result.ok() ? state_.changes_applied : state_.changes_refused);
  return result;
}

void SettingsSync::end_write(const std::string& refusals) {
  current_.last_refusal = refusals;
  std::lock_guard<std::mutex> lock(mutex_);
  state_.last_refusal = refusals;
}

void SettingsSync::publish_current() {
  server_->updateConfig(current_);
  mirror_.publish(current_);
}

session::AckResult SettingsSync::write(const std::string& name,
                                       const std::function<void(Config&)>& edit) {
  const SettingBinding* binding = find_binding(name);
  if (!binding) return session::AckResult::not_sent("no setting named '" + name + "'");
  boost::recursive_mutex::scoped_lock server_lock(server_mutex_);
  Config next = current_;
  edit(next);
  std::string refusals;
  const session::AckResult result = apply(*binding, next, refusals);
  end_write(refusals);
  publish_current();
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
    publish_current();
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
