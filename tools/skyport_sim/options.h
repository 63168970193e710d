// Command line of skyport_sim: where to serve, the credentials the payload is registered with
// (the app key from a file, never printed), the flight, the faults it starts with and the control
// socket. Arguments roslaunch adds (__name:=...) are ignored. `--help` prints skyport_usage().
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/protocol/result.h"
#include "k40t_driver/psdk/sim/adapter_simulator.h"
#include "k40t_driver/sim/sim_options.h"

namespace k40t::skyport_sim {

struct SkyportSimOptions {
  std::string link = "pty:///tmp/skyport";  // the transport URL opened (server side)
  psdk::sim::AdapterOptions adapter;
  std::optional<std::string> control_endpoint;
  std::vector<sim::ScheduledFault> scheduled;  // --silence, --disconnect, --seq-jump
  bool help = false;
};

// Parses argv (without the program name). Errors name the option and what is wrong, never the
// key itself.
Result<SkyportSimOptions> parse_options(const std::vector<std::string>& args);
std::string usage();

}  // namespace k40t::skyport_sim
