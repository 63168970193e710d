// SIGTERM as a second Ctrl-C for the standalone nodes. roscpp turns SIGINT into a shutdown request
// but leaves SIGTERM at its default (the process dies at once: no thread joined, exit code -15),
// and SIGTERM is what roslaunch sends after its SIGINT timeout, and what systemd and docker send.
#pragma once

namespace k40t::driver {

// After ros::init(): SIGTERM requests the same orderly shutdown as SIGINT.
void shutdown_on_sigterm();

}  // namespace k40t::driver
