// Command line of k40t_sim: where to serve, the decisions (docs/protocol/decisions.md) the pod
// follows, its world, the faults it starts with, capture and the control socket. Arguments
// roslaunch adds (__name:=...,
// __log:=...) are ignored. `--help` prints sim_usage().
#pragma once

#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/result.h"
#include "k40t_driver/sim/fault_injector.h"
#include "k40t_driver/sim/pod_model.h"

namespace k40t::sim {

// A fault that happens once, `at` after the start.
struct ScheduledFault {
  enum class Kind { kSilence, kDisconnect, kSequenceJump } kind = Kind::kSilence;
  std::chrono::milliseconds at{0};
  double amount = 0;  // seconds, or frames for a sequence jump
};

struct SimOptions {
  std::string link = "pty:///tmp/k40t_pod";  // the transport URL actually opened (server side)
  protocol::CrcCoverage crc_coverage = protocol::CrcCoverage::kHeaderExcluded;
  protocol::CodecOptions codec;
  PodConfig pod;
  std::optional<std::string> sd_condition;  // "absent", "fill", ...
  FaultSettings faults;
  std::vector<ScheduledFault> scheduled;
  uint32_t seed = 1;
  std::optional<std::string> capture_prefix;
  std::optional<std::string> control_endpoint;
  std::optional<int> rtsp_port;  // serve the video on rtsp://127.0.0.1:PORT/live/single (0: any)
  int rtsp_key_interval = 30;    // frames between the stream's key frames
  double tick_s = 0.01;          // model step and report scheduling period
  // The GPS request (0x000310) leaves this long after its photo (a real pod's processing), so
  // the time of day it carries is in the past by then.
  double gps_request_delay_s = 0;
  bool verbose = false;
  bool help = false;
};

// "AT:AMOUNT" (seconds after the start : seconds, or frames for a sequence jump), for --silence,
// --disconnect and --seq-jump; errors name `option`.
Result<ScheduledFault> parse_scheduled_fault(const std::string& option, const std::string& text,
                                             ScheduledFault::Kind kind, double max_amount);

// Parses argv (without the program name). Errors name the option and what is wrong.
Result<SimOptions> parse_sim_options(const std::vector<std::string>& args);
std::string sim_usage();

// `--link` accepts the host's view of the link and returns the server side the simulator opens:
//   pty:/path or pty:///path  -> pty:///path
//   udp://host:port           -> udp-server://host:port
//   tcp://host:port           -> tcp-server://host:port
//   udp-server://, tcp-server:// unchanged
Result<std::string> server_side_url(const std::string& link);

}  // namespace k40t::sim
