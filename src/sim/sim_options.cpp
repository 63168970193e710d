#include "k40t_driver/sim/sim_options.h"

#include "k40t_driver/protocol/conventions.h"
#include "k40t_driver/sim/number_text.h"
#include "k40t_driver/sim/option_kinds.h"

#include <cmath>
#include <cstdlib>
#include <sstream>

namespace k40t::sim {

namespace {

using OptionSpec = sim::OptionSpec<SimOptions>;
using Kinds = OptionKinds<SimOptions>;

OptionSpec byte_order_option(const char* name, const char* argument, const char* help,
                             Kinds::Field<protocol::ByteOrder> field) {
  return {name, argument, help,
          [=](SimOptions& o, const std::string& option, const std::string& v) {
            const auto order = protocol::parse_byte_order(v);
            if (!order) return Status::fail(option + ": " + order.error());
            field(o) = *order;
            return Status::ok();
          }};
}

const std::vector<OptionSpec>& option_table() {
  static const std::vector<OptionSpec> kOptions = {
      Kinds::link("where to serve: pty:/tmp/k40t_pod (default; creates the pty and the symlink), "
                  "udp://127.0.0.1:PORT, tcp://127.0.0.1:PORT (the server side of each)"),
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
      byte_order_option(
          "--ack-byte-order", "big|little",
          "docs/protocol/decisions.md#a2: byte order of ACK fields (default big)",
          [](SimOptions& o) -> protocol::ByteOrder& { return o.codec.ack_byte_order; }),
      byte_order_option(
          "--laser-status-byte-order", "little|big",
          "byte order of status frame 0x020406 (default little, section 2.1)",
          [](SimOptions& o) -> protocol::ByteOrder& { return o.codec.laser_status_byte_order; }),
      Kinds::number<int>(
          "--angle-scale", "N",
          "docs/protocol/decisions.md#a4: 0x000012 angles are degrees x N (default 100)", 1,
          protocol::kMaxAngleCommandScale,
          [](SimOptions& o) -> int& { return o.codec.angle_command_scale; }),
      Kinds::number<uint8_t>(
          "--gimbal-system-id", "N",
          "docs/protocol/decisions.md#a3: system id the gimbal answers from (default 3)", 1, 255,
          [](SimOptions& o) -> uint8_t& { return o.codec.gimbal_address.system; }),
      {"--convention", "NAME=VALUE",
       "one of the document's open readings the pod follows (docs/protocol/decisions.md"
       "#conventions; repeatable; the names of k40t probe and the driver's parameters); not "
       "auto: a pod has one reading",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         if (v.size() > 5 && v.compare(v.size() - 5, 5, "=auto") == 0)
           return Status::fail(option + " " + v + ": a pod has one reading, not auto");
         const Status set = protocol::set_convention_assignment({o.crc_coverage, o.codec}, v);
         return set ? set : Status::fail(option + ": " + set.message());
       }},
      Kinds::number<double>(
          "--gimbal-roll", "DEG",
          "the roll joint holds this angle, right-down positive (default 0; the attitude "
          "report's Euler order shows only with a roll)",
          -45.0, 45.0, [](SimOptions& o) -> double& { return o.pod.gimbal.roll_deg; }),
      Kinds::number<double>("--ground-height", "M",
                            "flat ground this far below the pod (default 30 m)", 1.0, 10000.0,
                            [](SimOptions& o) -> double& { return o.pod.world.ground_height_m; }),
      Kinds::number<double>(
          "--velocity-north", "M/S", "the vehicle flies north at this speed (default 0)", -100.0,
          100.0, [](SimOptions& o) -> double& { return o.pod.vehicle.velocity_north_m_s; }),
      Kinds::number<double>(
          "--velocity-east", "M/S", "the vehicle flies east at this speed (default 0)", -100.0,
          100.0, [](SimOptions& o) -> double& { return o.pod.vehicle.velocity_east_m_s; }),
      Kinds::flag("--gimbal-yaw-continuous",
                  "the gimbal's yaw turns through +-180 (no end stops; the default has them)",
                  [](SimOptions& o) -> bool& { return o.pod.gimbal.yaw_continuous; }),
      Kinds::number<double>("--gps-delay", "S",
                            "the GPS request leaves this long after its photo (default 0)", 0.0,
                            5.0, [](SimOptions& o) -> double& { return o.gps_request_delay_s; }),
      Kinds::number<double>(
          "--hot-object-temp", "DEGC", "temperature of the hot object (default 85)", -40.0, 2000.0,
          [](SimOptions& o) -> double& { return o.pod.world.hot.temperature_degC; }),
      Kinds::number<double>("--sd-capacity-mb", "MB", "SD card size (default 65536)", 64.0,
                            655350.0,
                            [](SimOptions& o) -> double& { return o.pod.camera.sd.capacity_mb; }),
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
      Kinds::flag("--single-shot-status",
                  "send photo status frames for single shots too (the document sends none)",
                  [](SimOptions& o) -> bool& { return o.pod.camera.single_shot_status; }),
      Kinds::number<double>("--corrupt-rate", "P", "probability per byte sent of a flipped bit",
                            0.0, 1.0,
                            [](SimOptions& o) -> double& { return o.faults.corrupt_rate; }),
      Kinds::number<double>("--garbage-rate", "P",
                            "probability per frame of random bytes before it", 0.0, 1.0,
                            [](SimOptions& o) -> double& { return o.faults.garbage_rate; }),
      Kinds::number<size_t>("--garbage-max", "N", "at most N garbage bytes at a time (default 16)",
                            1, 64,
                            [](SimOptions& o) -> size_t& { return o.faults.garbage_max_bytes; }),
      Kinds::number<double>("--drop-ack-rate", "P", "probability that a request gets no ACK", 0.0,
                            1.0, [](SimOptions& o) -> double& { return o.faults.drop_ack_rate; }),
      Kinds::number<double>("--delay-ack-ms", "MS", "send ACKs this late", 0.0, 60000.0,
                            [](SimOptions& o) -> double& { return o.faults.delay_ack_ms; }),
      Kinds::number<double>("--delay-ack-rate", "P",
                            "probability that an ACK is delayed (default 1)", 0.0, 1.0,
                            [](SimOptions& o) -> double& { return o.faults.delay_ack_rate; }),
      Kinds::scheduled("--silence", "AT:S",
                       "send nothing for S seconds, AT seconds after the start",
                       ScheduledFault::Kind::kSilence, 3600),
      Kinds::scheduled("--disconnect", "AT:S",
                       "close the link for S seconds, AT seconds after the start",
                       ScheduledFault::Kind::kDisconnect, 3600),
      Kinds::scheduled("--seq-jump", "AT:N", "skip N sequence numbers, AT seconds after the start",
                       ScheduledFault::Kind::kSequenceJump, 255),
      Kinds::number<uint32_t>("--seed", "N", "seed of the fault generator (default 1)", 0,
                              4294967295.0, [](SimOptions& o) -> uint32_t& { return o.seed; }),
      Kinds::text("--capture", "PREFIX",
                  "record every byte to PREFIX.tx.bin (sent) and PREFIX.rx.bin (received)",
                  [](SimOptions& o) -> std::optional<std::string>& { return o.capture_prefix; }),
      Kinds::text("--control", "ENDPOINT",
                  "control socket: PORT or tcp:127.0.0.1:PORT (loopback only) or unix:/path (see "
                  "'help' on it)",
                  [](SimOptions& o) -> std::optional<std::string>& { return o.control_endpoint; }),
      {"--rtsp-port", "PORT",
       "also serve the pod's video on rtsp://127.0.0.1:PORT/live/single (the pod's own is port "
       "558), rendered from the model: image mode, palette, zoom and gimbal show in the picture; "
       "0 picks a free port",
       [](SimOptions& o, const std::string& option, const std::string& v) {
         const auto port = parse_number_in(v, option, 0, 65535);
         if (!port) return port.status();
         if (*port != std::floor(*port))
           return Status::fail(option + ": '" + v + "' is not a port number");
         o.rtsp_port = static_cast<int>(*port);
         return Status::ok();
       }},
      Kinds::number<int>("--rtsp-key-interval", "N",
                         "frames between key frames of the --rtsp-port stream (default 30: a "
                         "late subscriber to the passthrough video waits up to N frames)",
                         1, 600, [](SimOptions& o) -> int& { return o.rtsp_key_interval; }),
      Kinds::flag("--verbose", "print every frame sent and received",
                  [](SimOptions& o) -> bool& { return o.verbose; }),
      Kinds::flag("--help", "this text", [](SimOptions& o) -> bool& { return o.help; }),
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
  const auto at = parse_number_in(text.substr(0, colon), option + " AT", 0, 86400);
  if (!at) return at.status();
  const auto amount = parse_number_in(text.substr(colon + 1), option + " AMOUNT", 0, max_amount);
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
