// The SKYPORT bridge's private parameters (docs/skyport.md), read and checked in one place.
#pragma once

#include <string>

#include <ros/node_handle.h>

#include "k40t_driver/protocol/result.h"
#include "k40t_driver/psdk/aes.h"
#include "k40t_driver/skyport/skyport_bridge.h"

namespace k40t::driver::skyport {

struct SkyportConfig {
  std::string device;  // SKYPORT UART URL
  int baud = 115200;
  psdk::Credentials credentials;  // never logged
  bool encryption = true;
  BridgeOptions bridge;
  bool feed_pod = true;              // publish fix/attitude/time_reference for the PodNodelet
  std::string feed_fix = "raw_gps";  // raw_gps or rtk: which push becomes `fix`
  std::string world_frame = "enu";
  std::string base_frame = "base_link";
  std::string reconfigure = "driver/set_parameters";
  double service_timeout_s = 2.0;
  double ack_timeout_s = 1.0;
  double silence_timeout_s = 1.0;  // no frame for this long: the adapter is silent (ERROR)
  double diagnostic_period_s = 1.0;
  // sensor_msgs/TimeReference whose header.stamp is the local time of each PPS rising edge (a PPS
  // driver's output); empty: none, the UTC push's 500 ms rule cannot be applied (3.3.10).
  std::string pps_topic;
  double pod_stale_s = 3.0;  // no status from the pod for this long: its state is stale (WARN)
  // skyport/get_position: the least time between two requests to the adapter.
  double position_min_interval_s = 0.2;
};

// Reads the private parameters; the app key comes from `app_key_file` (or `app_key`). A missing
// required value, a wrong type or an out-of-range value is an error naming the parameter.
Result<SkyportConfig> read_skyport_config(const ros::NodeHandle& private_nh);

}  // namespace k40t::driver::skyport
