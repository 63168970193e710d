// Reading private parameters with one line each: a wrong type or an out-of-range value records
// the first error, naming the parameter, what it got and what it accepts; check error() once at
// the end. Shared by the driver's and the video nodelet's parameter readers.
#pragma once

#include <array>
#include <sstream>
#include <string>
#include <vector>

#include <ros/node_handle.h>

namespace k40t::driver {

// Collects the first error so that every parameter is read with one line and checked once.
class ParamReader {
 public:
  explicit ParamReader(const ros::NodeHandle& nh) : nh_(nh) {}

  template <class T>
  T get(const std::string& name, const T& fallback) {
    T value = fallback;
    if (nh_.hasParam(name) && !nh_.getParam(name, value)) fail(name, "has the wrong type");
    return value;
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
    if (error_.empty()) error_ = "parameter " + nh_.resolveName(name) + " " + why;
  }
  const std::string& error() const { return error_; }

 private:
  const ros::NodeHandle& nh_;
  std::string error_;
};

}  // namespace k40t::driver
