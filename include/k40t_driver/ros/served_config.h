// The configuration type SettingsSync's dynamic_reconfigure::Server is instantiated with:
// K40tConfig with two of the steps the server calls on its ConfigType by name replaced, because
// both made the server lie or wait:
//   - __clamp__(): the server clamps every request into the cfg ranges before its callback, so that
//     `palette 99` reached the pod as 20, unannounced. Here nothing is clamped: SettingsSync
//     refuses a value outside the cfg range with a message (outside_cfg_range(),
//     setting_binding.h), and a value the pod reports outside a range (photo resolution 0x16) stays
//     as reported.
//   - __toServer__(): each time the server publishes a configuration it first writes every
//     parameter to the parameter server, one XML-RPC round trip to the master each (~50 of them:
//     10-25 ms) under the lock that serialises the writes, which made a `set_palette` answer take
//     13 ms instead of 0.3. Here it writes nothing; ParamMirror (param_mirror.h) writes the
//     parameters that changed a moment later, from a ROS timer, outside that lock.
#pragma once

#include <ros/node_handle.h>

#include "k40t_driver/ros/setting_binding.h"

namespace k40t::driver {

struct ServedConfig : Config {
  ServedConfig() = default;
  // The server assigns its statics (__getDefault__(), __getMin__(), ...) to ServedConfig members.
  ServedConfig(const Config& config) : Config(config) {}  // NOLINT(google-explicit-constructor)

  void __clamp__() {}
  void __toServer__(const ros::NodeHandle&) const {}
};

}  // namespace k40t::driver
