#include "options.h"

#include <sstream>

#include "k40t_driver/psdk/app_key_file.h"
#include "k40t_driver/sim/number_text.h"
#include "k40t_driver/sim/option_table.h"
#include "k40t_driver/sim/sim_options.h"

namespace k40t::skyport_sim {

namespace {

using psdk::sim::AdapterOptions;

using OptionSpec = sim::OptionSpec<SkyportSimOptions>;

Status set_number(double& field, const std::string& option, const std::string& value, double lo,
                  double hi) {
  const auto v = sim::parse_number_in(value, option, lo, hi);
  if (!v) return v.status();
  field = *v;
  return Status::ok();
}

// A probability 0..1 in one field of the adapter's fault options (o.adapter.*kGroup.*kField).
template <auto kGroup, auto kField>
Status set_rate(SkyportSimOptions& o, const std::string& option, const std::string& value) {
  return set_number(o.adapter.*kGroup.*kField, option, value, 0.0, 1.0);
}

Status set_text(std::string& field, const std::string& option, const std::string& value) {
  if (value.empty()) return Status::fail(option + ": empty");
  field = value;
  return Status::ok();
}

Status schedule(SkyportSimOptions& o, const std::string& option, const std::string& value,
                sim::ScheduledFault::Kind kind, double max_amount) {
  const auto fault = sim::parse_scheduled_fault(option, value, kind, max_amount);
  if (!fault) return fault.status();
  o.scheduled.push_back(*fault);
  return Status::ok();
}

const std::vector<OptionSpec>& option_table() {
  static const std::vector<OptionSpec> kOptions = {
      {"--link", "URL",
       "where to serve: pty:/tmp/skyport (default; creates the pty and the symlink the payload "
       "opens as serial:///tmp/skyport), udp://127.0.0.1:PORT, tcp://127.0.0.1:PORT",
       [](SkyportSimOptions& o, const std::string&, const std::string& v) {
         const auto url = sim::server_side_url(v);
         if (!url) return url.status();
         o.link = *url;
         return Status::ok();
       }},
      {"--app-key-file", "PATH",
       "file whose first line is the app key the payload must prove (never printed)",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         const auto key = psdk::read_app_key_file(v);
         if (!key) return Status::fail(option + ": " + key.error());
         o.adapter.credentials.app_key = *key;
         return Status::ok();
       }},
      {"--app-name", "NAME", "app name (part of the AES key)",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         return set_text(o.adapter.credentials.app_name, option, v);
       }},
      {"--app-id", "ID", "app id (part of the AES key)",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         return set_text(o.adapter.credentials.app_id, option, v);
       }},
      {"--developer-account", "ACCOUNT", "developer account (part of the AES key)",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         return set_text(o.adapter.credentials.developer_account, option, v);
       }},
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
      {"--ack-timeout-ms", "MS", "how long to wait for the payload's ACKs (default 500)",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         double ms = 0;
         const Status s = set_number(ms, option, v, 10, 60000);
         o.adapter.ack_timeout = std::chrono::milliseconds(static_cast<int64_t>(ms));
         return s;
       }},
      {"--identity-interval", "S", "seconds between identity verifications (default 30)",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         double s = 0;
         const Status status = set_number(s, option, v, 0.1, 86400);
         o.adapter.identity_interval = std::chrono::milliseconds(static_cast<int64_t>(s * 1000));
         return status;
       }},
      {"--power-off-after", "S", "announce power-off this many seconds after the start",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         double s = 0;
         const Status status = set_number(s, option, v, 0, 86400);
         o.adapter.flight.power_off_after_s = s;
         return status;
       }},
      {"--corrupt-rate", "P", "probability per byte sent of a flipped bit",
       set_rate<&AdapterOptions::byte_faults, &psdk::sim::ByteFaults::corrupt_rate>},
      {"--garbage-rate", "P", "probability per frame of random bytes before it",
       set_rate<&AdapterOptions::byte_faults, &psdk::sim::ByteFaults::garbage_rate>},
      {"--garbage-max", "N", "at most N garbage bytes at a time (default 16)",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         double n = 0;
         const Status s = set_number(n, option, v, 1, 64);
         o.adapter.byte_faults.garbage_max_bytes = static_cast<size_t>(n);
         return s;
       }},
      {"--drop-ack-rate", "P", "probability that a payload command gets no ACK",
       set_rate<&AdapterOptions::protocol_faults, &psdk::sim::ProtocolFaults::drop_ack_rate>},
      {"--delay-ack-ms", "MS", "send ACKs this late",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         return set_number(o.adapter.protocol_faults.delay_ack_ms, option, v, 0.0, 60000.0);
       }},
      {"--delay-ack-rate", "P", "probability that an ACK is delayed (default 1)",
       set_rate<&AdapterOptions::protocol_faults, &psdk::sim::ProtocolFaults::delay_ack_rate>},
      {"--seq-jump-rate", "P", "probability per command of a jump of 1..100 sequence numbers",
       set_rate<&AdapterOptions::protocol_faults, &psdk::sim::ProtocolFaults::sequence_jump_rate>},
      {"--silence", "AT:S", "send nothing for S seconds, AT seconds after the start",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         return schedule(o, option, v, sim::ScheduledFault::Kind::kSilence, 3600);
       }},
      {"--disconnect", "AT:S", "close the link for S seconds, AT seconds after the start",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         return schedule(o, option, v, sim::ScheduledFault::Kind::kDisconnect, 3600);
       }},
      {"--seq-jump", "AT:N", "skip N sequence numbers, AT seconds after the start",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         return schedule(o, option, v, sim::ScheduledFault::Kind::kSequenceJump, 65535);
       }},
      {"--seed", "N", "seed of the random bytes and the fault dice (default 1)",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         double n = 0;
         const Status s = set_number(n, option, v, 0, 4294967295.0);
         o.adapter.seed = static_cast<uint32_t>(n);
         o.adapter.byte_faults.seed = o.adapter.seed;
         return s;
       }},
      {"--control", "ENDPOINT",
       "control socket: PORT, tcp:127.0.0.1:PORT or unix:/path (send 'help' on it)",
       [](SkyportSimOptions& o, const std::string& option, const std::string& v) {
         if (v.empty()) return Status::fail(option + ": empty");
         o.control_endpoint = v;
         return Status::ok();
       }},
      {"--help", nullptr, "this text",
       [](SkyportSimOptions& o, const std::string&, const std::string&) {
         o.help = true;
         return Status::ok();
       }},
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
