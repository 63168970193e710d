#include "k40t_driver/ros/bag/yaml_params.h"

#include <yaml-cpp/yaml.h>

namespace k40t::driver {

namespace {

// A scalar as YAML 1.1 / rosparam types it: booleans, integers, reals, else a string.
XmlRpc::XmlRpcValue scalar(const YAML::Node& node) {
  if (node.Tag() == "!") return XmlRpc::XmlRpcValue(node.Scalar());  // quoted: a string
  bool b = false;
  if (YAML::convert<bool>::decode(node, b)) return XmlRpc::XmlRpcValue(b);
  int i = 0;
  if (YAML::convert<int>::decode(node, i)) return XmlRpc::XmlRpcValue(i);
  double d = 0;
  if (YAML::convert<double>::decode(node, d)) return XmlRpc::XmlRpcValue(d);
  return XmlRpc::XmlRpcValue(node.Scalar());
}

XmlRpc::XmlRpcValue convert(const YAML::Node& node) {
  XmlRpc::XmlRpcValue out;
  if (node.IsScalar()) return scalar(node);
  if (node.IsSequence()) {
    out.setSize(static_cast<int>(node.size()));
    for (size_t i = 0; i < node.size(); ++i) out[static_cast<int>(i)] = convert(node[i]);
  } else if (node.IsMap()) {
    out.begin();  // an empty struct, not an invalid value
    for (const auto& member : node) out[member.first.as<std::string>()] = convert(member.second);
  }
  return out;
}

}  // namespace

Result<XmlRpc::XmlRpcValue> load_yaml_params(const std::string& path) {
  try {
    const YAML::Node root = YAML::LoadFile(path);
    if (!root.IsMap())
      return Result<XmlRpc::XmlRpcValue>::fail(path + ": not a mapping of parameter names");
    return convert(root);
  } catch (const YAML::Exception& e) {
    return Result<XmlRpc::XmlRpcValue>::fail(path + ": " + e.what());
  }
}

}  // namespace k40t::driver
