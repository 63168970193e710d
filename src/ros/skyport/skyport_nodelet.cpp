// k40t_driver/SkyportNodelet: the SKYPORT bridge in the driver's nodelet manager.
#include <pluginlib/class_list_macros.hpp>

#include "k40t_driver/ros/component_host.h"
#include "k40t_driver/ros/skyport/skyport_ros.h"

namespace k40t::driver::skyport {

class SkyportNodelet : public ComponentNodelet<SkyportRos> {
 public:
  // Multi-threaded handles: the pod's services are called while pushes keep arriving.
  SkyportNodelet() : ComponentNodelet("SKYPORT bridge", Callbacks::kConcurrent) {}
};

}  // namespace k40t::driver::skyport

PLUGINLIB_EXPORT_CLASS(k40t::driver::skyport::SkyportNodelet, nodelet::Nodelet)
