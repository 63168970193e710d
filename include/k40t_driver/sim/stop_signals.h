// SIGINT and SIGTERM for the simulator programs, taken synchronously: the constructor blocks them
// in the calling thread (and so in every thread started after it), wait() returns the one that
// came. No handler ever runs in the middle of a simulation step.
#pragma once

#include <csignal>

namespace k40t::sim {

class StopSignals {
 public:
  StopSignals() {
    sigemptyset(&set_);
    sigaddset(&set_, SIGINT);
    sigaddset(&set_, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &set_, nullptr);
  }
  // Blocks until SIGINT or SIGTERM; returns it.
  int wait() const {
    int signal = 0;
    sigwait(&set_, &signal);
    return signal;
  }

 private:
  sigset_t set_;
};

}  // namespace k40t::sim
