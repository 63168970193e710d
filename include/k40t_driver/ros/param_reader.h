// Reading private parameters with one line each: a wrong type or an out-of-range value records
// the first error, naming the parameter, what it got and what it accepts; check error() once at
// the end. Shared by the driver's and the video nodelet's parameter readers. Reads the parameter
// server, or (offline, no master: `k40t bag`) a struct of values such as a YAML file's.
#pragma once

#include <array>
#include <sstream>
#include <string>
#include <vector>

#include <ros/node_handle.h>
#include <xmlrpcpp/XmlRpcValue.h>

namespace k40t::driver {

// An offline parameter value as roscpp's getParam would convert it (an integer is also a double).
bool from_xmlrpc(XmlRpc::XmlRpcValue& in, std::string& out);
bool from_xmlrpc(XmlRpc::XmlRpcValue& in, bool& out);
bool from_xmlrpc(XmlRpc::XmlRpcValue& in, int& out);
bool from_xmlrpc(XmlRpc::XmlRpcValue& in, double& out);
bool from_xmlrpc(XmlRpc::XmlRpcValue& in, std::vector<double>& out);
template <class T>
bool from_xmlrpc(XmlRpc::XmlRpcValue&, T&) {
  return false;  // a type no offline reader needs yet: reported as a wrong type
}

// Collects the first error so that every parameter is read with one line and checked once.
class ParamReader {
 public:
  explicit ParamReader(const ros::NodeHandle& nh) : nh_(&nh), ns_(nh.getNamespace()) {}
  // Offline: `params` is a struct of name -> value; `ns` names the parameters in errors.
  ParamReader(const XmlRpc::XmlRpcValue& params, const std::string& ns)
      : params_(params), ns_(ns) {}

  template <class T>
  T get(const std::string& name, const T& fallback) {
    T value = fallback;
    const bool wrong_type = nh_ ? nh_->hasParam(name) && !nh_->getParam(name, value)
                                : params_.getType() == XmlRpc::XmlRpcValue::TypeStruct &&
                                      params_.hasMember(name) && !from_xmlrpc(params_[name], value);
    if (wrong_type) fail(name, "has the wrong type");
    return value;
  }
  // Whether the parameter is set (on the server, or in the offline struct).
  bool has(const std::string& name) {
    return nh_ ? nh_->hasParam(name)
               : params_.getType() == XmlRpc::XmlRpcValue::TypeStruct && params_.hasMember(name);
  }
  double number(const std::string& name, double fallback, double lo, double hi) {
    const double value = get(name, fallback);
    if (!(value >= lo && value <= hi)) {
      std::ostringstream why;
      why << "must be " << lo << ".." << hi << ", got " << value;
      fail(name, why.str());
    }
    return value;
  }
  std::array<double, 3> xyz(const std::string& name, const std::array<double, 3>& fallback) {
    std::vector<double> v = get(name, std::vector<double>(fallback.begin(), fallback.end()));
    if (v.size() != 3) {
      fail(name,
           "must be a list of 3 numbers [x, y, z] in metres, got " + std::to_string(v.size()));
      return fallback;
    }
    return {v[0], v[1], v[2]};
  }
  void fail(const std::string& name, const std::string& why) {
    if (error_.empty()) {
      const std::string resolved = nh_ ? nh_->resolveName(name) : ns_ + "/" + name;
      error_ = "parameter " + resolved + " " + why;
    }
  }
  const std::string& error() const { return error_; }

 private:
  const ros::NodeHandle* nh_ = nullptr;
  XmlRpc::XmlRpcValue params_;
  std::string ns_;
  std::string error_;
};

}  // namespace k40t::driver
