#include "k40t_driver/ros/stop_signals.h"

#include <csignal>

#include <ros/init.h>

namespace k40t::driver {

namespace {

// ros::requestShutdown() only sets a flag that roscpp's own thread acts on, which is what makes
// it usable from a signal handler (roscpp's SIGINT handler calls it the same way).
void request_shutdown(int) {
  ros::requestShutdown();
}

}  // namespace

void shutdown_on_sigterm() {
  struct sigaction action {};
  action.sa_handler = request_shutdown;
  sigemptyset(&action.sa_mask);
  sigaction(SIGTERM, &action, nullptr);
}

}  // namespace k40t::driver
