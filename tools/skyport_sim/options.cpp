#include "options.h"

#include <sstream>

#include "k40t_driver/psdk/app_key_file.h"
#include "k40t_driver/sim/option_kinds.h"
#include "k40t_driver/sim/sim_options.h"

namespace k40t::skyport_sim {

namespace {

using psdk::sim::AdapterOptions;

using OptionSpec = sim::OptionSpec<SkyportSimOptions>;
using Kinds = sim::OptionKinds<SkyportSimOptions>;

// A probability 0..1 in one field of the adapter's fault options (o.adapter.*kGroup.*kField).
template <auto kGroup, auto kField>
OptionSpec rate_option(const char* name, const char* help) {
  return Kinds::number<double>(name, "P", help, 0.0, 1.0, [](SkyportSimOptions& o) -> double& {
    return o.adapter.*kGroup.*kField;
  });
}

const std::vector<OptionSpec>& option_table() {
  static const std::vector<OptionSpec> kOptions = {
      Kinds::link("where to serve: pty:/tmp/skyport (default; creates the pty and the symlink the "
                  "payload opens as serial:///tmp/skyport), udp://127.0.0.1:PORT, "
                  "tcp://127.0.0.1:PORT"),
      {"--app-key-file", "PATH",
       "file whose first line is the app key the payload must prove (never printed)",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         const auto key = psdk::read_app_key_file(v);
         if (!key) return Status::fail(option + ": " + key.error());
         o.adapter.credentials.app_key = *key;
         return Status::ok();
       }},
      Kinds::text(
          "--app-name", "NAME", "app name (part of the AES key)",
          [](SkyportSimOptions& o) -> std::string& { return o.adapter.credentials.app_name; }),
      Kinds::text(
          "--app-id", "ID", "app id (part of the AES key)",
          [](SkyportSimOptions& o) -> std::string& { return o.adapter.credentials.app_id; }),
      Kinds::text("--developer-account", "ACCOUNT", "developer account (part of the AES key)",
                  [](SkyportSimOptions& o) -> std::string& {
                    return o.adapter.credentials.developer_account;
                  }),
      {"--no-encryption", nullptr, "read and write plain frames only (no AES key)",
       [](SkyportSimOptions& o, const std::string&, const std::string&) {
         o.adapter.encryption = false;
         return Status::ok();
       }},
      {"--payload-layout", "dji_headers|document",
       "how the checks read the gimbal mode, SD card bits and interval where DJI's headers and the "
       "document disagree (default dji_headers; docs/psdk.md P28..P30)",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         if (psdk::sim::parse_payload_reading(v, o.adapter.reading)) return Status::ok();
         return Status::fail(option + ": dji_headers or document, got '" + v + "'");
       }},
      Kinds::number_to("--ack-timeout-ms", "MS",
                       "how long to wait for the payload's ACKs (default 500)", 10, 60000,
                       [](SkyportSimOptions& o, double ms) {
                         o.adapter.ack_timeout =
                             std::chrono::milliseconds(static_cast<int64_t>(ms));
                       }),
      Kinds::number_to("--identity-interval", "S",
                       "seconds between identity verifications (default 30)", 0.1, 86400,
                       [](SkyportSimOptions& o, double s) {
                         o.adapter.identity_interval =
                             std::chrono::milliseconds(static_cast<int64_t>(s * 1000));
                       }),
      Kinds::number_to(
          "--power-off-after", "S", "announce power-off this many seconds after the start", 0,
          86400, [](SkyportSimOptions& o, double s) { o.adapter.flight.power_off_after_s = s; }),
      rate_option<&AdapterOptions::byte_faults, &psdk::sim::ByteFaults::corrupt_rate>(
          "--corrupt-rate", "probability per byte sent of a flipped bit"),
      rate_option<&AdapterOptions::byte_faults, &psdk::sim::ByteFaults::garbage_rate>(
          "--garbage-rate", "probability per frame of random bytes before it"),
      Kinds::number<size_t>(
          "--garbage-max", "N", "at most N garbage bytes at a time (default 16)", 1, 64,
          [](SkyportSimOptions& o) -> size_t& { return o.adapter.byte_faults.garbage_max_bytes; }),
      rate_option<&AdapterOptions::protocol_faults, &psdk::sim::ProtocolFaults::drop_ack_rate>(
          "--drop-ack-rate", "probability that a payload command gets no ACK"),
      Kinds::number<double>(
          "--delay-ack-ms", "MS", "send ACKs this late", 0.0, 60000.0,
          [](SkyportSimOptions& o) -> double& { return o.adapter.protocol_faults.delay_ack_ms; }),
      rate_option<&AdapterOptions::protocol_faults, &psdk::sim::ProtocolFaults::delay_ack_rate>(
          "--delay-ack-rate", "probability that an ACK is delayed (default 1)"),
      rate_option<&AdapterOptions::protocol_faults, &psdk::sim::ProtocolFaults::sequence_jump_rate>(
          "--seq-jump-rate", "probability per command of a jump of 1..100 sequence numbers"),
      Kinds::scheduled("--silence", "AT:S",
                       "send nothing for S seconds, AT seconds after the start",
                       sim::ScheduledFault::Kind::kSilence, 3600),
      Kinds::scheduled("--disconnect", "AT:S",
                       "close the link for S seconds, AT seconds after the start",
                       sim::ScheduledFault::Kind::kDisconnect, 3600),
      Kinds::scheduled("--seq-jump", "AT:N", "skip N sequence numbers, AT seconds after the start",
                       sim::ScheduledFault::Kind::kSequenceJump, 65535),
      Kinds::number_to("--seed", "N", "seed of the random bytes and the fault dice (default 1)", 0,
                       4294967295.0,
                       [](SkyportSimOptions& o, double n) {
                         o.adapter.seed = static_cast<uint32_t>(n);
                         o.adapter.byte_faults.seed = o.adapter.seed;
                       }),
      Kinds::text(
          "--control", "ENDPOINT",
          "control socket: PORT, tcp:127.0.0.1:PORT or unix:/path (send 'help' on it)",
          [](SkyportSimOptions& o) -> std::optional<std::string>& { return o.control_endpoint; }),
      Kinds::flag("--help", "this text", [](SkyportSimOptions& o) -> bool& { return o.help; }),
  };
  return kOptions;
}

}  // namespace

Result<SkyportSimOptions> parse_options(const std::vector<std::string>& args) {
  SkyportSimOptions options;
  const Status parsed = parse_option_table(option_table(), args, options);
  if (!parsed) return parsed;
  if (!options.help && options.adapter.credentials.app_key.empty())
    return Status::fail("--app-key-file is required (the key the payload must prove)");
  return options;
}

std::string usage() {
  std::ostringstream out;
  out << "usage: skyport_sim --app-key-file PATH [options]\n"
         "A simulated DJI SKYPORT adapter (PSDK v1): identity verification, data pushes from a\n"
         "simulated flight, camera and gimbal commands on demand (control socket).\n\n";
  out << option_table_usage(option_table());
  return out.str();
}

}  // namespace k40t::skyport_sim
