#include "k40t_driver/ros/start_failure.h"

#include <utility>

namespace k40t::driver {

StartFailure::StartFailure(ros::NodeHandle nh, ros::NodeHandle private_nh, std::string what,
                           std::string why)
    : what_(std::move(what)),
      why_(std::move(why)),
      updater_(nh, private_nh, private_nh.getNamespace()) {
  updater_.setHardwareID("none");
  updater_.add("configuration", [this](diagnostic_updater::DiagnosticStatusWrapper& stat) {
    stat.summary(diagnostic_msgs::DiagnosticStatus::ERROR, what_ + " not started: " + why_);
    stat.add("component", what_);
    stat.add("error", why_);
  });
  updater_.force_update();
  timer_ = nh.createSteadyTimer(ros::WallDuration(1.0),
                                [this](const ros::SteadyTimerEvent&) { updater_.force_update(); });
}

}  // namespace k40t::driver
