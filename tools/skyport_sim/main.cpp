// skyport_sim: a simulated DJI SKYPORT adapter (PSDK v1) for the payload side of the K40T driver.
//   skyport_sim --link pty:/tmp/skyport --app-key-file KEY [--control unix:/tmp/skyport.ctl]
//               [--app-name N --app-id I --developer-account A] [faults...]
// Runs until SIGINT/SIGTERM. Exit codes: 0 normal, 1 could not start, 2 bad arguments. The app key
// is read from a file and never printed.
#include <csignal>
#include <cstdio>
#include <string>
#include <vector>

#include "control.h"
#include "fault_schedule.h"
#include "k40t_driver/sim/control_server.h"
#include "k40t_driver/sim/stop_signals.h"
#include "k40t_driver/transport/transport.h"
#include "options.h"

int main(int argc, char** argv) {
  using namespace k40t;
  const std::vector<std::string> args(argv + 1, argv + argc);
  auto options = skyport_sim::parse_options(args);
  if (!options) {
    std::fprintf(stderr, "skyport_sim: %s\n", options.error().c_str());
    return 2;
  }
  if (options->help) {
    std::fputs(skyport_sim::usage().c_str(), stdout);
    return 0;
  }

  // Signals are taken by this thread (sigwait); every thread started below inherits the mask.
  const k40t::sim::StopSignals stop_signals;

  auto link = transport::make_transport(options->link);
  if (!link) {
    std::fprintf(stderr, "skyport_sim: %s\n", link.error().c_str());
    return 2;
  }
  psdk::sim::AdapterSimulator adapter(std::move(link.value()), options->adapter);
  const Status started = adapter.start();
  if (!started) {
    std::fprintf(stderr, "skyport_sim: %s\n", started.message().c_str());
    return 1;
  }
  std::printf("skyport_sim: serving %s (%s)\n", options->link.c_str(),
              options->adapter.encryption ? "AES on" : "AES off");

  sim::ControlServer control;
  if (options->control_endpoint) {
    const Status listening = control.start(*options->control_endpoint, [&](const std::string& l) {
      return skyport_sim::handle_control(adapter, l);
    });
    if (!listening) {
      std::fprintf(stderr, "skyport_sim: %s\n", listening.message().c_str());
      adapter.stop();
      return 1;
    }
    std::printf("skyport_sim: control socket %s\n", options->control_endpoint->c_str());
  }
  skyport_sim::FaultSchedule schedule(adapter, options->scheduled);
  std::fflush(stdout);

  const int signal = stop_signals.wait();
  const psdk::sim::AdapterStats stats = adapter.stats();
  std::printf("skyport_sim: %s, stopping; identity passed %llu, failed %llu\n",
              signal == SIGINT ? "interrupted" : "terminated",
              static_cast<unsigned long long>(stats.identity_passed),
              static_cast<unsigned long long>(stats.identity_failed));
  schedule.stop();
  control.stop();
  adapter.stop();
  return 0;
}
