// A PSDK version as an operator writes it in a parameter ("A.B.C.D"), ROS-free so that the rule is
// unit-tested and the ROS glue (ros/skyport/skyport_config.cpp) only reads the parameter.
#pragma once

#include <string>

#include "k40t_driver/psdk/commands/payload_state.h"

namespace k40t::driver::skyport {

// "A.B.C.D", each a decimal 0..255 (3.1.2: 0xAABBCCDD is version AA.BB.CC.DD), nothing after D.
// false (and `out` untouched) for anything else.
bool parse_version(const std::string& text, psdk::Version& out);

}  // namespace k40t::driver::skyport
