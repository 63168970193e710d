// A component's standalone node: the whole main() over roscpp alone, without the nodelet library,
// so that a node does not load nodelet's class loader, roslib, rospack and through it libpython
// (~3 MB of resident pages). The component's nodelet is in component_host.h.
#pragma once

#include <memory>

#include <ros/ros.h>

#include "k40t_driver/ros/callback_threads.h"
#include "k40t_driver/ros/start_failure.h"
#include "k40t_driver/ros/stop_signals.h"
#include "k40t_driver/transport/thread_name.h"

namespace k40t::driver {

enum class Callbacks {
  kOneAtATime,  // nodelet: the default handles; node: ros::spin()
  kConcurrent,  // nodelet: the multi-threaded handles; node: four callback threads
                // (callback_threads.h)
};

// The whole main() of a standalone node named `node_name`.
// Threads are named for `top -H` (transport/thread_name.h): roscpp's own (poll, XML-RPC, rosout,
// timers) inherit "k40t_roscpp", the spinner's "k40t_spin"; the main thread keeps the program's
// name (the process name ps and pkill match).
template <class Component>
int run_standalone_node(int argc, char** argv, const char* node_name, const char* what,
                        Callbacks callbacks) {
  const transport::SavedThreadName program_name;
  transport::name_this_thread("k40t_roscpp");
  // Our own SIGINT handler instead of roscpp's: the same shutdown request, remembered for
  // shutdown_requested().
  ros::init(argc, argv, node_name, ros::init_options::NoSigintHandler);
  shutdown_on_stop_signals();
  ros::NodeHandle nh;
  ros::NodeHandle private_nh("~");
  // Ctrl-C while loading, or before the NodeHandles started roscpp (which would not act on it)
  if (stop_requested_before_ros_start() || shutdown_requested()) return 0;
  auto component = Component::create(nh, private_nh);
  // One that cannot start stays running with the reason as an ERROR diagnostic (start_failure.h)
  std::unique_ptr<StartFailure> failure;
  if (!component) {
    ROS_FATAL("%s not started: %s", what, component.error().c_str());
    failure = std::make_unique<StartFailure>(nh, private_nh, what, component.error());
  }
  const int exit_code = failure ? 1 : 0;
  if (callbacks == Callbacks::kOneAtATime) {
    program_name.restore();
    ros::spin();
    return exit_code;
  }
  transport::name_this_thread("k40t_spin");
  CallbackThreads threads(*ros::getGlobalCallbackQueue(), 4);
  program_name.restore();
  // The threads end when ros::shutdown() disables the queue; roscpp then finishes stopping
  // (ros::waitForShutdown() polls only for that moment) before the component is destroyed.
  threads.wait();
  ros::waitForShutdown();
  return exit_code;
}

}  // namespace k40t::driver
