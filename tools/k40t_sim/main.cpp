// k40t_sim: the simulated K40T pod (see docs/simulator.md).
//   k40t_sim --link pty:/tmp/k40t_pod [--control 5761] [--capture /tmp/pod] [--rtsp-port 8554]
//            [faults...]
// Runs until SIGINT/SIGTERM. Exit codes: 0 normal, 1 could not start, 2 bad arguments.
#include <csignal>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "k40t_driver/sim/pod_server.h"
#include "k40t_driver/sim/stop_signals.h"
#include "k40t_driver/sim/video/model_snapshot.h"
#include "k40t_driver/sim/video/rtsp_stream_server.h"

namespace {

// The link as the host sees it, for the start-up line.
std::string host_side(const std::string& url) {
  if (url.rfind("pty://", 0) == 0) return "serial://" + url.substr(6) + " (pty)";
  if (url.rfind("udp-server://", 0) == 0) return "udp://" + url.substr(13);
  if (url.rfind("tcp-server://", 0) == 0) return "tcp://" + url.substr(13);
  return url;
}

}  // namespace

int main(int argc, char** argv) {
  const std::vector<std::string> args(argv + 1, argv + argc);
  auto options = k40t::sim::parse_sim_options(args);
  if (!options) {
    std::fprintf(stderr, "k40t_sim: %s\n", options.error().c_str());
    return 2;
  }
  if (options->help) {
    std::fputs(k40t::sim::sim_usage().c_str(), stdout);
    return 0;
  }

  // Signals are taken synchronously by this thread (sigwait), so every thread started below
  // inherits the blocked mask and no handler runs in the middle of the simulation.
  const k40t::sim::StopSignals stop_signals;

  k40t::sim::PodServer server(*options);
  const k40t::Status started = server.start();
  if (!started) {
    std::fprintf(stderr, "k40t_sim: %s\n", started.message().c_str());
    return 1;
  }
  std::printf("k40t_sim: serving %s; connect the host to %s\n", options->link.c_str(),
              host_side(options->link).c_str());
  if (options->control_endpoint) {
    std::printf("k40t_sim: control socket %s", options->control_endpoint->c_str());
    if (server.control_port() > 0) std::printf(" (port %d)", server.control_port());
    std::printf("\n");
  }
  std::unique_ptr<k40t::sim::video::RtspStreamServer> video;
  if (options->rtsp_port) {
    k40t::sim::video::RtspServerOptions video_options;
    video_options.port = *options->rtsp_port;
    video_options.key_frame_interval = options->rtsp_key_interval;
    auto started_video = k40t::sim::video::RtspStreamServer::start(video_options, [&server] {
      k40t::sim::video::VideoSnapshot snapshot;
      server.with_model(
          [&](k40t::sim::PodModel& model) { snapshot = k40t::sim::video::snapshot_of(model); });
      return snapshot;
    });
    if (!started_video) {
      std::fprintf(stderr, "k40t_sim: %s\n", started_video.error().c_str());
      server.stop();
      return 1;
    }
    video = std::move(started_video.value());
    std::printf("k40t_sim: video %s\n", video->url().c_str());
  }
  if (options->capture_prefix) {
    std::printf("k40t_sim: capturing to %s.tx.bin and %s.rx.bin\n",
                options->capture_prefix->c_str(), options->capture_prefix->c_str());
  }
  std::fflush(stdout);

  const int signal = stop_signals.wait();
  std::printf("k40t_sim: %s, stopping; %s\n", signal == SIGINT ? "interrupted" : "terminated",
              server.status().c_str());
  video.reset();
  server.stop();
  return 0;
}
