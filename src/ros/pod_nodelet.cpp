// k40t_driver/PodNodelet: the driver inside a nodelet manager (zero-copy to other nodelets).
#include <pluginlib/class_list_macros.hpp>

#include "k40t_driver/ros/component_host.h"
#include "k40t_driver/ros/ros_pod.h"

namespace k40t::driver {

class PodNodelet : public ComponentNodelet<RosPod> {
 public:
  // Multi-threaded handles: a service waiting for an ACK must not hold up the others.
  PodNodelet() : ComponentNodelet("K40T driver", Callbacks::kConcurrent) {}
};

}  // namespace k40t::driver

PLUGINLIB_EXPORT_CLASS(k40t::driver::PodNodelet, nodelet::Nodelet)
