// A ControlTarget for tests of the simulator's control language: the faults and a pod model of
// its own, the last disconnect asked for, and a fixed status line.
#pragma once

#include <chrono>
#include <functional>
#include <string>

#include "k40t_driver/sim/control_commands.h"
#include "k40t_driver/sim/fault_injector.h"
#include "k40t_driver/sim/pod_model.h"

namespace k40t::sim::testing {

class FakeTarget : public ControlTarget {
 public:
  FaultInjector& faults() override { return faults_; }
  void disconnect_for(std::chrono::milliseconds duration) override { disconnected_for = duration; }
  void with_model(const std::function<void(PodModel&)>& change) override { change(pod); }
  std::string status() override { return "fine"; }

  FaultInjector faults_;
  PodModel pod;
  std::chrono::milliseconds disconnected_for{-1};
};

}  // namespace k40t::sim::testing
