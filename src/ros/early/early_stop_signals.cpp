// Catches SIGINT and SIGTERM from the start of the process: the executable's .preinit_array runs
// before any shared library's initialiser, and the node's libraries (the video node loads ~290:
// OpenCV, GStreamer, ...) take 0.1 to 0.3 s to initialise on a loaded machine. Without it a Ctrl-C
// or a SIGTERM in that window killed the process by the signal's default action (exit -2 / -15)
// before roscpp had installed its handler (test/stop/clean_stop.py). The handler only remembers the
// request; main() asks stop_requested_before_ros_start() once roscpp and shutdown_on_stop_signals() have
// taken the signals over.
#include <csignal>

#include "k40t_driver/ros/stop_signals.h"

namespace {

volatile std::sig_atomic_t g_stop_requested = 0;

void remember_stop(int) {
  g_stop_requested = 1;
}

void catch_stop_signals_early(int, char**, char**) {
  struct sigaction action {};
  action.sa_handler = remember_stop;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

// Only an executable may have a .preinit_array: this file is a static library linked into each
// node, pulled in by main()'s call of stop_requested_before_ros_start().
__attribute__((section(".preinit_array"),
               used)) void (*const kCatchStopSignalsEarly)(int, char**,
                                                           char**) = catch_stop_signals_early;

}  // namespace

namespace k40t::driver {

bool stop_requested_before_ros_start() {
  return g_stop_requested != 0;
}

}  // namespace k40t::driver
