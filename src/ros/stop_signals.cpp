#include "k40t_driver/ros/stop_signals.h"

#include <atomic>
#include <csignal>

#include <ros/init.h>

namespace k40t::driver {

namespace {

std::atomic<bool> g_stop_signalled{false};  // lock-free: written from signal handlers

// ros::requestShutdown() only sets a flag that roscpp's own thread acts on, which is what makes
// it usable from a signal handler (roscpp's SIGINT handler calls it the same way).
void request_shutdown(int) {
  note_stop_signal();
  ros::requestShutdown();
}

}  // namespace

void shutdown_on_stop_signals() {
  struct sigaction action {};
  action.sa_handler = request_shutdown;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

void note_stop_signal() {
  g_stop_signalled.store(true);
}

bool shutdown_requested() {
  return g_stop_signalled.load() || ros::isShuttingDown();
}

}  // namespace k40t::driver
