// The services that change or re-read settings dynamic_reconfigure also shows: set_palette and
// set_photo_mode write through SettingsSync::write() (the one write path per setting, so the
// published configuration is what the pod last accepted), read_settings re-reads 0x000100 and
// 0x000200 (and the camera and gimbal reports) on demand and republishes the configuration. In
// replay mode there is no SettingsSync: they answer that nothing can be sent.
#pragma once

#include <vector>

#include <ros/node_handle.h>
#include <ros/service_server.h>

#include "k40t_driver/ros/settings_sync.h"

namespace k40t::driver {

class SettingsServices {
 public:
  SettingsServices(ros::NodeHandle nh, SettingsSync* settings);

 private:
  // Writes the setting the table assigns to `service` (SettingBinding::service).
  session::AckResult write(const std::string& service, const std::function<void(Config&)>& edit);

  ros::NodeHandle nh_;
  SettingsSync* settings_;  // nullptr in replay mode
  std::vector<ros::ServiceServer> servers_;
};

}  // namespace k40t::driver
