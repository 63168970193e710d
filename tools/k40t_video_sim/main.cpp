// k40t_video_sim: the simulated pod's RTSP video on its own, without the pod model (the scene is
// the model's default world) — for tests, benchmarks and trying a video client. k40t_sim
// --rtsp-port serves the same stream driven by the live pod model. What it shows is set by options
// and by control lines on stdin (snapshot_commands.h: mode, palette, zoom, thermal_zoom, gimbal,
// resolution).
//
//   k40t_video_sim --port 8554 --mode 0 --palette 5
//   echo "zoom 10" > the process's stdin
#include <chrono>
#include <csignal>
#include <cstdlib>
#include <iostream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "k40t_driver/sim/stop_signals.h"
#include "k40t_driver/sim/video/rtsp_stream_server.h"
#include "k40t_driver/sim/video/snapshot_commands.h"
#include "k40t_driver/sim/world.h"

namespace {

using k40t::sim::video::RtspServerOptions;
using k40t::sim::video::VideoSnapshot;

const char kUsage[] =
    "usage: k40t_video_sim [options]\n"
    "  --address A        bind address (default 127.0.0.1)\n"
    "  --port P           RTSP port, 0 = any free one (default 8554)\n"
    "  --path /P          mount path (default /live/single)\n"
    "  --fps N            frame rate (default 30)\n"
    "  --bitrate K        encoder bitrate in kbit/s (default 4000)\n"
    "  --key-interval N   frames between key frames (default 30)\n"
    "  --codec C          h264 (x264, default) or h265 (x265)\n"
    "  --mode M           image mode 0 thermal, 5/6 visible, 7 split (default 5)\n"
    "  --palette N        thermal palette 1..20\n"
    "  --zoom X           telephoto hybrid zoom 1..160\n"
    "  --thermal-zoom N   thermal digital zoom 1..8\n"
    "  --resolution R     1080 or 720\n"
    "  --gimbal Y,P       boresight yaw and pitch in degrees\n"
    "  --sweep D          turn the yaw at D deg/s (every frame differs, like a moving camera)\n"
    "Control lines on stdin take the same settings: 'mode 0', 'palette 3', 'zoom 12.5',\n"
    "'thermal_zoom 2', 'gimbal 30 -10', 'resolution 720'.\n";

struct Options {
  RtspServerOptions server;
  double sweep_deg_s = 0;
  std::vector<std::string> commands;  // initial settings, as control lines
};

int parse_int(const std::string& option, const std::string& value) {
  size_t used = 0;
  int n = 0;
  try {
    n = std::stoi(value, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != value.size()) {
    std::cerr << "k40t_video_sim: " << option << " expects an integer, got '" << value << "'\n";
    std::exit(2);
  }
  return n;
}

Options parse(int argc, char** argv) {
  Options options;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--help" || option == "-h") {
      std::cout << kUsage;
      std::exit(0);
    }
    if (i + 1 >= argc) {
      std::cerr << "k40t_video_sim: " << option << " needs a value\n" << kUsage;
      std::exit(2);
    }
    const std::string value = argv[++i];
    if (option == "--address") {
      options.server.address = value;
    } else if (option == "--port") {
      options.server.port = parse_int(option, value);
    } else if (option == "--path") {
      options.server.path = value;
    } else if (option == "--fps") {
      options.server.fps = parse_int(option, value);
    } else if (option == "--bitrate") {
      options.server.bitrate_kbps = parse_int(option, value);
    } else if (option == "--key-interval") {
      options.server.key_frame_interval = parse_int(option, value);
    } else if (option == "--codec") {
      k40t::Result<k40t::video::Codec> codec = k40t::video::parse_codec(value);
      if (!codec) {
        std::cerr << "k40t_video_sim: --codec: " << codec.error() << "\n";
        std::exit(2);
      }
      options.server.codec = codec.value();
    } else if (option == "--sweep") {
      try {
        options.sweep_deg_s = std::stod(value);
      } catch (const std::exception&) {
        std::cerr << "k40t_video_sim: --sweep expects degrees per second, got '" << value << "'\n";
        std::exit(2);
      }
    } else if (option == "--gimbal") {
      std::string line = "gimbal " + value;
      for (char& c : line) c = c == ',' ? ' ' : c;
      options.commands.push_back(line);
    } else if (option == "--mode" || option == "--palette" || option == "--zoom" ||
               option == "--thermal-zoom" || option == "--resolution") {
      std::string name = option.substr(2);
      for (char& c : name) c = c == '-' ? '_' : c;
      options.commands.push_back(name + " " + value);
    } else {
      std::cerr << "k40t_video_sim: unknown option " << option << "\n" << kUsage;
      std::exit(2);
    }
  }
  return options;
}

}  // namespace

int main(int argc, char** argv) {
  const Options options = parse(argc, argv);

  std::mutex mutex;
  VideoSnapshot snapshot;
  // The pod model's default world (hot object, cold pond, ground, sky), without the pod model.
  const k40t::sim::World world;
  snapshot.temperature = [world](const k40t::sim::Vec3& d) {
    return world.trace(d).temperature_degC;
  };
  for (const std::string& line : options.commands) {
    if (k40t::Status s = k40t::sim::video::apply_command(line, snapshot); !s) {
      std::cerr << "k40t_video_sim: " << s.message() << "\n";
      return 2;
    }
  }

  // Block the stop signals before any thread starts, so that only sigwait() below sees them.
  const k40t::sim::StopSignals stop_signals;

  const auto started = std::chrono::steady_clock::now();
  auto server = k40t::sim::video::RtspStreamServer::start(options.server, [&] {
    std::lock_guard<std::mutex> lock(mutex);
    VideoSnapshot now = snapshot;
    const double elapsed_s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    now.yaw_deg += options.sweep_deg_s * elapsed_s;
    return now;
  });
  if (!server) {
    std::cerr << "k40t_video_sim: " << server.error() << "\n";
    return 1;
  }
  std::cout << "k40t_video_sim: serving " << server.value()->url() << std::endl;

  std::thread control([&] {
    std::string line;
    while (std::getline(std::cin, line)) {
      std::lock_guard<std::mutex> lock(mutex);
      VideoSnapshot next = snapshot;
      if (k40t::Status s = k40t::sim::video::apply_command(line, next); !s) {
        std::cerr << "k40t_video_sim: " << s.message() << std::endl;
      } else {
        snapshot = next;
      }
    }
  });
  control.detach();  // blocked in getline until stdin closes; the process exit ends it

  stop_signals.wait();
  const auto counters = server.value()->counters();
  std::cout << "k40t_video_sim: stopping after " << counters.frames_pushed << " frames"
            << std::endl;
  server.value().reset();
  return 0;
}
