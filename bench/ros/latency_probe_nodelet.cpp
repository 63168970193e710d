// k40t_driver/LatencyProbeNodelet: the probe inside the driver's nodelet manager, where
// joint_states arrives by pointer (no serialisation, no socket).
#include <nodelet/nodelet.h>
#include <pluginlib/class_list_macros.hpp>

#include "latency_probe.h"

namespace k40t::bench {

class LatencyProbeNodelet : public nodelet::Nodelet {
 private:
  void onInit() override {
    probe_ = std::make_unique<LatencyProbe>(getNodeHandle(), getPrivateNodeHandle());
  }
  std::unique_ptr<LatencyProbe> probe_;
};

}  // namespace k40t::bench

PLUGINLIB_EXPORT_CLASS(k40t::bench::LatencyProbeNodelet, nodelet::Nodelet)
