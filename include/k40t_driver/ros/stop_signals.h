// SIGTERM as a second Ctrl-C for the standalone nodes. roscpp turns SIGINT into a shutdown request
// but leaves SIGTERM at its default (the process dies at once: no thread joined, exit code -15),
// and SIGTERM is what roslaunch sends after its SIGINT timeout, and what systemd and docker send.
#pragma once

namespace k40t::driver {

// After ros::init(): SIGTERM requests the same orderly shutdown as SIGINT.
void shutdown_on_sigterm();

// Whether SIGINT or SIGTERM arrived before roscpp's handlers were in place: between the loading of
// the node's libraries and its first NodeHandle (roscpp installs its SIGINT handler then). The
// standalone nodes ask it after creating their NodeHandles and exit 0 at once if so. Defined in
// the library k40t_early_stop_signals (src/ros/early/), which every node executable links.
bool stop_requested_before_ros_start();

}  // namespace k40t::driver
