// k40t_skyport_node: the SKYPORT bridge as a standalone node (the same SkyportRos as the nodelet).
#include "k40t_driver/ros/component_host.h"
#include "k40t_driver/ros/skyport/skyport_ros.h"

int main(int argc, char** argv) {
  // Pushes keep being published while a command waits for the pod's service.
  return k40t::driver::run_standalone_node<k40t::driver::skyport::SkyportRos>(
      argc, argv, "k40t_skyport", "SKYPORT bridge", k40t::driver::Callbacks::kConcurrent);
}
