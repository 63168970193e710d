// k40t_driver/SkyportNodelet: the SKYPORT bridge in the driver's nodelet manager.
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "k40t_driver/ros/skyport/skyport_ros.h"

namespace k40t::driver::skyport {

class SkyportNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    // Multi-threaded handles: the pod's services are called while pushes keep arriving.
    auto bridge = SkyportRos::create(getMTNodeHandle(), getMTPrivateNodeHandle());
    if (!bridge) {
      NODELET_FATAL("SKYPORT bridge not started: %s", bridge.error().c_str());
      return;
    }
    bridge_ = std::move(bridge.value());
  }

  std::unique_ptr<SkyportRos> bridge_;
};

}  // namespace k40t::driver::skyport

PLUGINLIB_EXPORT_CLASS(k40t::driver::skyport::SkyportNodelet, nodelet::Nodelet)
