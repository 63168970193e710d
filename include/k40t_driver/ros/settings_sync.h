// dynamic_reconfigure for the pod's settings (cfg/K40t.cfg). Keeps the published configuration
// equal to what the pod has:
//   - a change is sent as the one request that sets it; a value outside its cfg range is refused
//     without sending (nothing is clamped: served_config.h); if the pod refuses it (validation,
//     NACK, timeout) the parameter is put back to its previous value, which is what the server
//     then publishes (the reply to the request shows the values in force);
//   - a refusal is logged as an ERROR and kept, with its reason, in the read-only parameter
//     `last_refusal` (what `dynparam get` and rqt show) and in the `settings` diagnostic, until a
//     later write (a reconfigure request or a service call that sends something) is accepted
//     whole;
//   - publishing a configuration costs no round trip to the master (served_config.h), so a
//     service answers right after the pod's ACK with the change already published, under the
//     same lock as reconfigure requests (no race between the two);
//   - on every "pod online" event (connect, reconnect, pod back after silence) read_from_pod()
//     reads 0x000100 and 0x000200 and the next camera (0x000003) and gimbal (0x000001) status
//     reports, and publishes the result as the current configuration; settings the pod cannot
//     report and the user has set are sent again (a rebooted pod resumes periodic ranging).
// The binding of each parameter to its request and read-back is the settings table
// (setting_binding.h, settings_bindings.cpp).
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <dynamic_reconfigure/server.h>
#include <ros/node_handle.h>
#include <boost/thread/recursive_mutex.hpp>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/driver/pod_queries.h"
#include "k40t_driver/driver/setting_writes.h"
#include "k40t_driver/driver/settings_reader.h"
#include "k40t_driver/driver/settings_state.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/ros/param_mirror.h"
#include "k40t_driver/ros/served_config.h"
#include "k40t_driver/ros/setting_binding.h"

namespace k40t::driver {

class SettingsSync {
 public:
  SettingsSync(ros::NodeHandle private_nh, PodDriver& driver);

  // Blocking: call from the driver's online thread or the read_settings service (one read at a
  // time). Returns the read's state.
  SettingsState read_from_pod();
  SettingsState state() const;

  // The one write path of a setting, for services (set_palette, set_photo_mode, ...): `edit`
  // changes the configuration, the binding `name` sends its request whether or not the value
  // changed, and the configuration the server publishes is what the pod accepted. Blocking.
  session::AckResult write(const std::string& name, const std::function<void(Config&)>& edit);

 private:
  void on_reconfigure(Config& config, uint32_t level);
  // Sends `binding` for `next` unless a value it changes is outside its cfg range: on success
  // current_ takes its fields, otherwise `next` gets current_'s back and `refusals` the reason.
  // Server mutex held.
  session::AckResult apply(const SettingBinding& binding, Config& next, std::string& refusals);
  // A write that sent something ended: its refusals (empty: all accepted) become the last refusal.
  // Server mutex held.
  void end_write(const std::string& refusals);
  // current_ becomes the server's configuration. Server mutex held.
  void publish_current();

  PodDriver& driver_;
  SettingsReader reader_;  // the read side: settings ACKs and the next status reports
  const std::map<std::string, std::vector<std::string>> parameters_;  // binding -> cfg parameters
  ParamMirror mirror_;  // before server_: its callback publishes to it from the start
  boost::recursive_mutex server_mutex_;
  std::unique_ptr<dynamic_reconfigure::Server<ServedConfig>> server_;
  Config current_;  // what the pod has, and the last refusal (server mutex)
  bool initialised_ = false;
  SettingWrites writes_;   // what was written, and during which read (server mutex)
  std::mutex read_mutex_;  // one read_from_pod() at a time

  mutable std::mutex mutex_;  // guards what follows; never held while waiting for the pod
  SettingsState state_;
};

}  // namespace k40t::driver
