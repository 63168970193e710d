// k40t_driver/PodNodelet: the driver inside a nodelet manager (zero-copy to other nodelets).
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "k40t_driver/ros/ros_pod.h"

namespace k40t::driver {

class PodNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    // Multi-threaded handles: a service waiting for an ACK must not hold up the others.
    Result<std::unique_ptr<RosPod>> pod =
        RosPod::create(getMTNodeHandle(), getMTPrivateNodeHandle());
    if (!pod) {
      NODELET_FATAL("K40T driver not started: %s", pod.error().c_str());
      return;
    }
    pod_ = std::move(pod.value());
  }

  std::unique_ptr<RosPod> pod_;
};

}  // namespace k40t::driver

PLUGINLIB_EXPORT_CLASS(k40t::driver::PodNodelet, nodelet::Nodelet)
