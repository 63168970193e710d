// A component's standalone node: the whole main() over roscpp alone, without the nodelet library,
// so that a node does not load nodelet's class loader, roslib, rospack and through it libpython
// (~3 MB of resident pages). The component's nodelet is in component_host.h.
#pragma once

#include <ros/ros.h>

#include "k40t_driver/ros/stop_signals.h"
#include "k40t_driver/transport/thread_name.h"

namespace k40t::driver {

enum class Callbacks {
  kOneAtATime,  // nodelet: the default handles; node: ros::spin()
  kConcurrent,  // nodelet: the multi-threaded handles; node: a spinner of four threads
};

// The whole main() of a standalone node named `node_name`.
// Threads are named for `top -H` (transport/thread_name.h): roscpp's own (poll, XML-RPC, rosout,
// timers) inherit "k40t_roscpp", the spinner's "k40t_spin"; the main thread is "k40t_main".
template <class Component>
int run_standalone_node(int argc, char** argv, const char* node_name, const char* what,
                        Callbacks callbacks) {
  transport::name_this_thread("k40t_roscpp");
  ros::init(argc, argv, node_name);
  shutdown_on_sigterm();
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  if (stop_requested_before_ros_start()) return 0;  // Ctrl-C while loading
  auto component = Component::create(nh, private_nh);
  if (!component) {
    ROS_FATAL("%s not started: %s", what, component.error().c_str());
    return 1;
  }
  if (callbacks == Callbacks::kOneAtATime) {
    transport::name_this_thread("k40t_main");
    ros::spin();
    return 0;
  }
  ros::AsyncSpinner spinner(4);
  transport::name_this_thread("k40t_spin");
  spinner.start();
  transport::name_this_thread("k40t_main");
  ros::waitForShutdown();
  return 0;
}

}  // namespace k40t::driver
