// The driver's parameter file (config/k40t.yaml) without a parameter server: its top-level
// mapping as an XmlRpc struct, typed as `rosparam load` would (true/false booleans, integers,
// reals, strings, lists), for ParamReader.
#pragma once

#include <string>

#include <xmlrpcpp/XmlRpcValue.h>

#include "k40t_driver/protocol/result.h"

namespace k40t::driver {

Result<XmlRpc::XmlRpcValue> load_yaml_params(const std::string& path);

}  // namespace k40t::driver
