// SIGTERM as a second Ctrl-C for the standalone nodes. roscpp turns SIGINT into a shutdown request
// (which it keeps to itself) but leaves SIGTERM at its default (the process dies at once: no thread
// joined, exit code -15), and SIGTERM is what roslaunch sends after its SIGINT timeout, and what
// systemd and docker send.
#pragma once

namespace k40t::driver {

// After ros::init(..., NoSigintHandler): SIGINT and SIGTERM request the same orderly shutdown
// (ros::requestShutdown(), as roscpp's own SIGINT handler does) and are remembered for
// shutdown_requested().
void shutdown_on_stop_signals();

// From a signal handler of the process's own (k40t_manager's): remembers the request.
void note_stop_signal();

// Whether this process is stopping: a stop signal came (above) or roscpp is shutting down. A
// Ctrl-C reaches every process of the terminal at once, and the simulator may close the link
// before this process has stopped: such a loss is the shutdown's, not the pod's.
bool shutdown_requested();

// Whether SIGINT or SIGTERM arrived before roscpp's handlers were in place: between the loading of
// the node's libraries and its first NodeHandle (roscpp installs its SIGINT handler then). The
// standalone nodes ask it after creating their NodeHandles and exit 0 at once if so. Defined in
// the library k40t_early_stop_signals (src/ros/early/), which every node executable links.
bool stop_requested_before_ros_start();

}  // namespace k40t::driver
