#include "k40t_driver/sim/sim_options.h"

#include "k40t_driver/sim/number_text.h"
#include "k40t_driver/sim/option_table.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace k40t::sim {

namespace {

Result<double> parse_number(const std::string& option, const std::string& text, double lo,
                            double hi) {
  return parse_number_in(text, option, lo, hi);
}

using OptionSpec = sim::OptionSpec<SimOptions>;

// Sets a double field from a number within [lo, hi].
Status set_number(double& field, const std::string& option, const std::string& value, double lo,
                  double hi) {
  const auto v = parse_number(option, value, lo, hi);
  if (!v) return v.status();
  field = *v;
  return Status::ok();
}

const std::vector<OptionSpec>& option_table() {
  static const std::vector<OptionSpec> kOptions = {
      {"--link", "URL",
       "where to serve: pty:/tmp/k40t_pod (default; creates the pty and the symlink), "
       "udp://127.0.0.1:PORT, tcp://127.0.0.1:PORT (the server side of each)",
       [](SimOptions& o, const std::string&, const std::string& v) {
         const auto url = server_side_url(v);
         if (!url) return url.status();
         o.link = *url;
         return Status::ok();
       }},
      {"--crc-coverage", "header_excluded|whole_frame",
       "docs/protocol/decisions.md#a1: checksum coverage the pod uses, sending and receiving "
       "(default header_excluded)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         const auto c = protocol::parse_crc_coverage(v);
         if (!c) return Status::fail(option + ": " + c.error());
         if (*c == protocol::CrcCoverage::kAuto) {
           return Status::fail(
               option + ": a pod has one coverage: header_excluded or whole_frame, not auto");
         }
         o.crc_coverage = *c;
         return Status::ok();
       }},
      {"--ack-byte-order", "big|little",
       "docs/protocol/decisions.md#a2: byte order of ACK fields (default big)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         const auto order = protocol::parse_byte_order(v);
         if (!order) return Status::fail(option + ": " + order.error());
         o.codec.ack_byte_order = *order;
         return Status::ok();
       }},
      {"--laser-status-byte-order", "little|big",
       "byte order of status frame 0x020406 (default little, section 2.1)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         const auto order = protocol::parse_byte_order(v);
         if (!order) return Status::fail(option + ": " + order.error());
         o.codec.laser_status_byte_order = *order;
         return Status::ok();
       }},
      {"--angle-scale", "N",
       "docs/protocol/decisions.md#a4: 0x000012 angles are degrees x N (default 100)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         const auto n = parse_number(option, v, 1, 1000);
         if (!n) return n.status();
         o.codec.angle_command_scale = static_cast<int>(*n);
         return Status::ok();
       }},
      {"--gimbal-system-id", "N",
       "docs/protocol/decisions.md#a3: system id the gimbal answers from (default 3)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         const auto n = parse_number(option, v, 1, 255);
         if (!n) return n.status();
         o.codec.gimbal_address.system = static_cast<uint8_t>(*n);
         return Status::ok();
       }},
      {"--ground-height", "M", "flat ground this far below the pod (default 30 m)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         return set_number(o.pod.world.ground_height_m, option, v, 1.0, 10000.0);
       }},
      {"--velocity-north", "M/S", "the vehicle flies north at this speed (default 0)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         return set_number(o.pod.vehicle.velocity_north_m_s, option, v, -100.0, 100.0);
       }},
      {"--velocity-east", "M/S", "the vehicle flies east at this speed (default 0)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         return set_number(o.pod.vehicle.velocity_east_m_s, option, v, -100.0, 100.0);
       }},
      {"--gps-delay", "S", "the GPS request leaves this long after its photo (default 0)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         return set_number(o.gps_request_delay_s, option, v, 0.0, 5.0);
       }},
      {"--hot-object-temp", "DEGC", "temperature of the hot object (default 85)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         return set_number(o.pod.world.hot.temperature_degC, option, v, -40.0, 2000.0);
       }},
      {"--sd-capacity-mb", "MB", "SD card size (default 65536)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         return set_number(o.pod.camera.sd.capacity_mb, option, v, 64.0, 655350.0);
       }},
      {"--sd", "CONDITION",
       "start with the SD card absent, fill(ed), abnormal, slow or in format-error",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         SdCard probe;
         if (!set_sd_condition(probe, v)) {
           return Status::fail(option + ": expected one of " + sd_condition_names() + ", got '" +
                               v + "'");
         }
         o.sd_condition = v;
         return Status::ok();
       }},
      {"--single-shot-status", nullptr,
       "send photo status frames for single shots too (the document sends none)",
       [](SimOptions& o, const std::string&, const std::string&) {
         o.pod.camera.single_shot_status = true;
         return Status::ok();
       }},
      {"--corrupt-rate", "P", "probability per byte sent of a flipped bit",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         return set_number(o.faults.corrupt_rate, option, v, 0.0, 1.0);
       }},
      {"--garbage-rate", "P", "probability per frame of random bytes before it",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         return set_number(o.faults.garbage_rate, option, v, 0.0, 1.0);
       }},
      {"--garbage-max", "N", "at most N garbage bytes at a time (default 16)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         const auto n = parse_number(option, v, 1, 64);
         if (!n) return n.status();
         o.faults.garbage_max_bytes = static_cast<size_t>(*n);
         return Status::ok();
       }},
      {"--drop-ack-rate", "P", "probability that a request gets no ACK",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         return set_number(o.faults.drop_ack_rate, option, v, 0.0, 1.0);
       }},
      {"--delay-ack-ms", "MS", "send ACKs this late",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         return set_number(o.faults.delay_ack_ms, option, v, 0.0, 60000.0);
       }},
      {"--delay-ack-rate", "P", "probability that an ACK is delayed (default 1)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         return set_number(o.faults.delay_ack_rate, option, v, 0.0, 1.0);
       }},
      {"--silence", "AT:S", "send nothing for S seconds, AT seconds after the start",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         const auto f = parse_scheduled_fault(option, v, ScheduledFault::Kind::kSilence, 3600);
         if (!f) return f.status();
         o.scheduled.push_back(*f);
         return Status::ok();
       }},
      {"--disconnect", "AT:S", "close the link for S seconds, AT seconds after the start",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         const auto f = parse_scheduled_fault(option, v, ScheduledFault::Kind::kDisconnect, 3600);
         if (!f) return f.status();
         o.scheduled.push_back(*f);
         return Status::ok();
       }},
      {"--seq-jump", "AT:N", "skip N sequence numbers, AT seconds after the start",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         const auto f = parse_scheduled_fault(option, v, ScheduledFault::Kind::kSequenceJump, 255);
         if (!f) return f.status();
         o.scheduled.push_back(*f);
         return Status::ok();
       }},
      {"--seed", "N", "seed of the fault generator (default 1)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         const auto n = parse_number(option, v, 0, 4294967295.0);
         if (!n) return n.status();
         o.seed = static_cast<uint32_t>(*n);
         return Status::ok();
       }},
      {"--capture", "PREFIX",
       "record every byte to PREFIX.tx.bin (sent) and PREFIX.rx.bin (received)",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         if (v.empty()) return Status::fail(option + ": the prefix is empty");
         o.capture_prefix = v;
         return Status::ok();
       }},
      {"--control", "ENDPOINT",
       "control socket: PORT or tcp:127.0.0.1:PORT (loopback only) or unix:/path (see 'help' on "
       "it)",
       [](SimOptions& o, const std::string&, const std::string& v) {
         o.control_endpoint = v;
         return Status::ok();
       }},
      {"--rtsp-port", "PORT",
       "also serve the pod's video on rtsp://127.0.0.1:PORT/live/single (the pod's own is port "
       "558), rendered from the model: image mode, palette, zoom and gimbal show in the picture; "
       "0 picks a free port",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         const auto port = parse_number(option, v, 0, 65535);
         if (!port) return port.status();
         if (*port != std::floor(*port))
           return Status::fail(option + ": '" + v + "' is not a port number");
         o.rtsp_port = static_cast<int>(*port);
         return Status::ok();
       }},
      {"--verbose", nullptr, "print every frame sent and received",
       [](SimOptions& o, const std::string&, const std::string&) {
         o.verbose = true;
         return Status::ok();
       }},
      {"--help", nullptr, "this text",
       [](SimOptions& o, const std::string&, const std::string&) {
         o.help = true;
         return Status::ok();
       }},
  };
  return kOptions;
}

}  // namespace

// "AT:AMOUNT", both numbers.
Result<ScheduledFault> parse_scheduled_fault(const std::string& option, const std::string& text,
                                             ScheduledFault::Kind kind, double max_amount) {
  const size_t colon = text.find(':');
  if (colon == std::string::npos)
    return Status::fail(option + ": expected AT:AMOUNT (seconds:value), got '" + text + "'");
  const auto at = parse_number(option + " AT", text.substr(0, colon), 0, 86400);
  if (!at) return at.status();
  const auto amount = parse_number(option + " AMOUNT", text.substr(colon + 1), 0, max_amount);
  if (!amount) return amount.status();
  ScheduledFault fault;
  fault.kind = kind;
  fault.at = std::chrono::milliseconds(std::llround(*at * 1000));
  fault.amount = *amount;
  return fault;
}

Result<std::string> server_side_url(const std::string& link) {
  const auto starts = [&](const char* prefix) { return link.rfind(prefix, 0) == 0; };
  if (starts("pty:///")) return link;
  if (starts("pty:/") && !starts("pty://")) return "pty://" + link.substr(4);
  if (starts("udp-server://") || starts("tcp-server://")) return link;
  if (starts("udp://")) return "udp-server://" + link.substr(6);
  if (starts("tcp://")) return "tcp-server://" + link.substr(6);
  return Status::fail("--link: expected pty:/PATH, udp://HOST:PORT or tcp://HOST:PORT, got '" +
                      link + "'");
}

Result<SimOptions> parse_sim_options(const std::vector<std::string>& args) {
  SimOptions options;
  const Status parsed = parse_option_table(option_table(), args, options);
  if (!parsed) return parsed;
  return options;
}

std::string sim_usage() {
  std::ostringstream out;
  out << "usage: k40t_sim [options]\n"
         "A simulated K40T gimbal pod: serves the pod's protocol with a physically consistent "
         "model\n"
         "(gimbal, zoom, thermal scene, laser, camera and SD card) and misbehaves on demand.\n"
         "See docs/simulator.md. Exit codes: 0, 1 could not start, 2 bad arguments.\n\n";
  out << option_table_usage(option_table());
  out << "\nArguments of the form __name:=value (added by roslaunch) are ignored.\n";
  return out.str();
}

}  // namespace k40t::sim
