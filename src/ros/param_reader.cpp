#include "k40t_driver/ros/param_reader.h"

namespace k40t::driver {

using XmlRpc::XmlRpcValue;

bool from_xmlrpc(XmlRpcValue& in, std::string& out) {
  if (in.getType() != XmlRpcValue::TypeString) return false;
  out = static_cast<std::string>(in);
  return true;
}

bool from_xmlrpc(XmlRpcValue& in, bool& out) {
  if (in.getType() != XmlRpcValue::TypeBoolean) return false;
  out = static_cast<bool>(in);
  return true;
}

bool from_xmlrpc(XmlRpcValue& in, int& out) {
  if (in.getType() != XmlRpcValue::TypeInt) return false;
  out = static_cast<int>(in);
  return true;
}

bool from_xmlrpc(XmlRpcValue& in, double& out) {
  if (in.getType() == XmlRpcValue::TypeInt) {
    out = static_cast<int>(in);
    return true;
  }
  if (in.getType() != XmlRpcValue::TypeDouble) return false;
  out = static_cast<double>(in);
  return true;
}

bool from_xmlrpc(XmlRpcValue& in, std::vector<double>& out) {
  if (in.getType() != XmlRpcValue::TypeArray) return false;
  std::vector<double> values(static_cast<size_t>(in.size()));
  for (int i = 0; i < in.size(); ++i) {
    if (!from_xmlrpc(in[i], values[static_cast<size_t>(i)])) return false;
  }
  out = std::move(values);
  return true;
}

}  // namespace k40t::driver
