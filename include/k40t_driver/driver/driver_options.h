// Everything the driver needs to know before it starts, in one ROS-free struct. The ROS glue fills
// it from parameters (ros_params.h); tests and benchmarks fill it directly.
#pragma once

#include <set>
#include <string>

#include "k40t_driver/session/session.h"
#include "k40t_driver/transport/device_url.h"

namespace k40t::driver {

struct DriverOptions {
  // Device URL (transport.h); ignored in replay mode.
  std::string device;
  // Appended as ?baud= to serial URLs that carry none.
  int baud = 115200;
  // Frames come from replay_frame() instead of a device; nothing is ever sent.
  bool replay = false;
  // Longest wait between reconnection attempts (the first is after 50 ms, then doubling): bounds
  // how long after the pod's return the topics resume.
  double reconnect_max_delay_s = 1.0;

  // Codec decisions (docs/protocol/decisions.md#a1 to #a5), ACK timeout and retries. The open
  // readings (decisions.md#conventions) are session.codec.conventions.
  session::SessionOptions session;
  // The readings the user set (parameters, a conventions file); the others are defaults. Only for
  // the `conventions` diagnostic's "where it came from".
  std::set<std::string> conventions_from_parameters;

  // Seconds between time syncs (0x00030E, docs/protocol/decisions.md#a8); 0 disables.
  double time_sync_period_s = 10.0;
  // The time zone sent with every time sync (0x00030E, struct timezone's tz_minuteswest): the pod
  // names its files in local time. 0 = UTC; UTC+8 is -480. -840..720.
  int time_zone_minutes_west = 0;
  // gimbal/cmd_rate dead-man: no rate command for this long stops the gimbal.
  double cmd_rate_timeout_s = 0.5;
  // Answer the pod's GPS requests (0x000310) from set_vehicle_state().
  bool answer_gps_requests = true;
  // The GPS answer carries the heights as int16 x0.1 m (-3276.8..3276.7 m, section 3.2.4.15).
  // true: a height beyond that is sent as the nearest limit (the position still tags the photo);
  // false: such a request is answered with the failure code and no position.
  bool gps_clamp_height = true;
  // Answer a GPS request with the vehicle state at the requested time of day (the photo's),
  // interpolated in a history of the inputs; false: the latest state (the behaviour before
  // issue 12, kept to measure against).
  bool geotag_time_match = true;
  // Seconds of input history kept for those answers.
  double state_history_s = 10.0;
  // Seconds between laser-target requests (0x000320); 0 disables. Needs a vehicle fix.
  double laser_target_period_s = 1.0;
  // Seconds without a frame before the pod counts as silent; the next frame is a "pod online"
  // event (settings are re-read).
  double silence_timeout_s = 0.5;
  // Seconds without a valid frame before the link state turns from "waiting for the pod" or
  // "connected" to "no answer" (logged once; link_monitor.h). Longer than silence_timeout: a
  // normal start (the pod or the simulator booting) stays quiet.
  double link_timeout_s = 3.0;
};

using transport::device_url_with_baud;  // the ~device URL with ~baud applied

}  // namespace k40t::driver
