// The DJI app key from a file (its first line), so that it never has to appear on a command line
// or in a parameter dump. Used by the bridge and by skyport_sim.
#pragma once

#include <string>

#include "k40t_driver/codec/result.h"

namespace k40t::psdk {

// The first line of `path` without trailing white space; an error naming the file if it cannot be
// read or that line is empty. The error never contains the key.
Result<std::string> read_app_key_file(const std::string& path);

}  // namespace k40t::psdk
