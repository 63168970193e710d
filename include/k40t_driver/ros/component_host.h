// How the package's three components (RosPod, SkyportRos, VideoStreamer) are hosted, alike: each
// has `static Result<std::unique_ptr<C>> create(nh, private_nh)` and runs either in a nodelet
// manager (ComponentNodelet) or as a standalone node (run_standalone_node()). One that cannot
// start logs a fatal line naming it (`what`, e.g. "K40T driver") and the reason once, then stays
// loaded (nodelet) or running (node) with that reason as an ERROR diagnostic (start_failure.h):
// a respawning launch file does not restart it into the same error.
#pragma once

#include <memory>
#include <utility>

#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <pluginlib/class_list_macros.hpp>

#include "k40t_driver/ros/start_failure.h"
#include "k40t_driver/ros/stop_signals.h"
#include "k40t_driver/transport/thread_name.h"

namespace k40t::driver {

enum class Callbacks {
  kOneAtATime,  // nodelet: the default handles; node: ros::spin()
  kConcurrent,  // nodelet: the multi-threaded handles; node: a spinner of four threads
};

template <class Component>
class ComponentNodelet : public nodelet::Nodelet {
 protected:
  ComponentNodelet(const char* what, Callbacks callbacks) : what_(what), callbacks_(callbacks) {}

 private:
  void onInit() override {
    const bool concurrent = callbacks_ == Callbacks::kConcurrent;
    auto created =
        Component::create(concurrent ? getMTNodeHandle() : getNodeHandle(),
                          concurrent ? getMTPrivateNodeHandle() : getPrivateNodeHandle());
    if (!created) {
      NODELET_FATAL("%s not started: %s", what_, created.error().c_str());
      failure_ = std::make_unique<StartFailure>(getNodeHandle(), getPrivateNodeHandle(), what_,
                                                created.error());
      return;
    }
    component_ = std::move(created.value());
  }

  const char* what_;
  Callbacks callbacks_;
  std::unique_ptr<Component> component_;
  std::unique_ptr<StartFailure> failure_;
};

// Declares the nodelet class Namespace::Name hosting Component (its constructor gives `what` and
// Callbacks::`callbacks`) and exports it to pluginlib as nodelet_plugins.xml names it. At global
// scope, once per nodelet source file.
#define K40T_COMPONENT_NODELET(Namespace, Name, Component, what, callbacks)  \
  namespace Namespace {                                                      \
  class Name : public ::k40t::driver::ComponentNodelet<Component> {          \
   public:                                                                   \
    Name() : ComponentNodelet(what, ::k40t::driver::Callbacks::callbacks) {} \
  };                                                                         \
  }                                                                          \
  PLUGINLIB_EXPORT_CLASS(Namespace::Name, nodelet::Nodelet)

// The whole main() of a standalone node named `node_name`.
// Threads are named for `top -H` (transport/thread_name.h): roscpp's own (poll, XML-RPC, rosout,
// timers) inherit "k40t_roscpp", the spinner's "k40t_spin"; the main thread is "k40t_main".
template <class Component>
int run_standalone_node(int argc, char** argv, const char* node_name, const char* what,
                        Callbacks callbacks) {
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
  std::unique_ptr<StartFailure> failure;
  if (!component) {
    ROS_FATAL("%s not started: %s", what, component.error().c_str());
    failure = std::make_unique<StartFailure>(nh, private_nh, what, component.error());
  }
  const int exit_code = failure ? 1 : 0;
  if (callbacks == Callbacks::kOneAtATime) {
    transport::name_this_thread("k40t_main");
    ros::spin();
    return exit_code;
  }
  ros::AsyncSpinner spinner(4);
  transport::name_this_thread("k40t_spin");
  spinner.start();
  transport::name_this_thread("k40t_main");
  ros::waitForShutdown();
  return exit_code;
}

}  // namespace k40t::driver
