// A component (driver, video, SKYPORT bridge) that could not start because of its configuration
// (a bad parameter, a malformed device URL) stays up and says so, instead of exiting: a launch
// file that respawns its nodes would otherwise restart it into the same error forever, each
// restart printing the error again (k40t.launch respawns the driver, for the crash it never
// expects). The reason goes to the console once (the host's FATAL line) and to /diagnostics as an
// ERROR, every second until the node is stopped or the nodelet unloaded; fixing the parameter
// means restarting the node, as with every parameter read at start.
#pragma once

#include <string>

#include <diagnostic_updater/diagnostic_updater.h>
#include <ros/ros.h>

namespace k40t::driver {

class StartFailure {
 public:
  // `what`: the component ("K40T driver"); `why`: the error naming the parameter and its value.
  StartFailure(ros::NodeHandle nh, ros::NodeHandle private_nh, std::string what, std::string why);

 private:
  const std::string what_;
  const std::string why_;
  diagnostic_updater::Updater updater_;
  ros::SteadyTimer timer_;
};

}  // namespace k40t::driver
