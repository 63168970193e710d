// skyport_sim's faults given on the command line for later (--silence AT:S, --disconnect AT:S,
// --seq-jump AT:N): a thread fires each at its time after start(); stop() ends it at once.
#pragma once

#include <condition_variable>
#include <mutex>
#include <thread>
#include <vector>

#include "k40t_driver/psdk/sim/adapter_simulator.h"
#include "k40t_driver/sim/sim_options.h"

namespace k40t::skyport_sim {

class FaultSchedule {
 public:
  FaultSchedule(psdk::sim::AdapterSimulator& adapter, std::vector<sim::ScheduledFault> faults);
  ~FaultSchedule();  // stop()s
  void stop();

 private:
  void run();

  psdk::sim::AdapterSimulator& adapter_;
  std::vector<sim::ScheduledFault> faults_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::thread thread_;
};

}  // namespace k40t::skyport_sim
