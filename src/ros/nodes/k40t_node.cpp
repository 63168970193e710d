// k40t_node: the driver as a standalone node (the same RosPod as the nodelet, without nodelet).
#include "k40t_driver/ros/ros_pod.h"
#include "k40t_driver/ros/standalone_node.h"

int main(int argc, char** argv) {
  // Services block while they wait for an ACK; the other callbacks keep running meanwhile.
  return k40t::driver::run_standalone_node<k40t::driver::RosPod>(
      argc, argv, "k40t_driver", "K40T driver", k40t::driver::Callbacks::kConcurrent);
}
