// The control language of skyport_sim's socket: one command line, one reply line. Replies start
// with "ok" when the command ran (the reply then says what came back: an ACK's return code and
// data in hex, or a check's PASS/FAIL lines joined by " | ") and "error" otherwise. `help` lists
// the commands.
#pragma once

#include <string>

#include "k40t_driver/psdk/sim/adapter_simulator.h"

namespace k40t::skyport_sim {

std::string handle_control(psdk::sim::AdapterSimulator& adapter, const std::string& line);
std::string control_help();

}  // namespace k40t::skyport_sim
