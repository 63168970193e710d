// How the package's three components (RosPod, SkyportRos, VideoStreamer) are hosted, alike: each
// has `static Result<std::unique_ptr<C>> create(nh, private_nh)` and runs either in a nodelet
// manager (ComponentNodelet) or as a standalone node (run_standalone_node(), in standalone_node.h,
// which a node can include alone so as not to link the nodelet library). One that cannot
// start logs a fatal line naming it (`what`, e.g. "K40T driver") and the reason once, then stays
// loaded (nodelet) or running (node) with that reason as an ERROR diagnostic (start_failure.h):
// a respawning launch file does not restart it into the same error.
#pragma once

#include <memory>
#include <utility>

#include <nodelet/nodelet.h>
#include <ros/ros.h>
#include <pluginlib/class_list_macros.hpp>

#include "k40t_driver/ros/standalone_node.h"
#include "k40t_driver/ros/start_failure.h"

namespace k40t::driver {

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

}  // namespace k40t::driver
