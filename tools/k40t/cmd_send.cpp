// k40t send: one request over a link, the decoded ACK (or why none came) back.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "command.h"
#include "connection_waiter.h"
#include "frame_text.h"
#include "input.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/session/session.h"

namespace k40t::tool {

namespace {

struct Request {
  protocol::MessageId id = 0;
  protocol::Payload payload;
};

Result<protocol::MessageId> parse_message_id(const std::string& text) {
  char* end = nullptr;
  const unsigned long value = std::strtoul(text.c_str(), &end, 16);
  if (*end != '\0' || value > 0xFFFF) {
    return Result<protocol::MessageId>::fail("'" + text + "' is not a request id (0x0000..0xFFFF)");
  }
  return static_cast<protocol::MessageId>(value);
}

// COMMAND, name=value arguments and --payload -> the request to send.
Result<Request> build_request(const ParsedArgs& args, const protocol::CodecOptions& codec) {
  const std::string& command = args.positional[1];
  const bool hex_id = command.rfind("0x", 0) == 0 || command.rfind("0X", 0) == 0;
  const protocol::MessageInfo* info = nullptr;
  Request request;
  if (hex_id) {
    Result<protocol::MessageId> id = parse_message_id(command);
    if (!id) return id.status();
    request.id = id.value();
    info = protocol::find_message(request.id);
  } else {
    info = protocol::find_message(command);
    if (info == nullptr)
      return Result<Request>::fail("unknown message '" + command + "' (see 'k40t list')");
    request.id = info->id;
  }
  if (protocol::kind_of(request.id) != protocol::MessageKind::kRequestOrReport ||
      protocol::is_periodic_report(request.id) ||
      (info != nullptr && info->direction != protocol::Direction::kHostToPod)) {
    return Result<Request>::fail("'" + command + "' (" + id_text(request.id) + ", " +
                                 kind_name(request.id) + ") is not a request the host sends");
  }

  protocol::FieldArgs fields;
  for (size_t i = 2; i < args.positional.size(); ++i) {
    const std::string& arg = args.positional[i];
    const size_t equals = arg.find('=');
    if (equals == std::string::npos || equals == 0) {
      return Result<Request>::fail("expected name=value, got '" + arg + "'");
    }
    if (!fields.emplace(arg.substr(0, equals), arg.substr(equals + 1)).second) {
      return Result<Request>::fail("field '" + arg.substr(0, equals) + "' given twice");
    }
  }
  const auto payload_hex = args.options.find("--payload");
  if (payload_hex != args.options.end()) {
    if (!fields.empty())
      return Result<Request>::fail("give name=value fields or --payload, not both");
    Result<std::vector<uint8_t>> bytes = parse_hex(payload_hex->second);
    if (!bytes) return Result<Request>::fail("--payload: " + bytes.error());
    if (bytes->size() > protocol::kMaxPayloadSize) {
      return Result<Request>::fail("--payload: " + std::to_string(bytes->size()) +
                                   " bytes, the maximum is 243");
    }
    std::copy(bytes->begin(), bytes->end(), request.payload.bytes.begin());
    request.payload.size = bytes->size();
    return request;
  }
  if (info == nullptr)
    return Result<Request>::fail(id_text(request.id) +
                                 " is not in the catalogue: give --payload HEX");
  Result<protocol::Payload> encoded = info->encode_args(fields, codec);
  if (!encoded) return encoded.status();
  request.payload = encoded.value();
  return request;
}

int run_send(const Command& self, const ParsedArgs& args) {
  Result<WireOptions> wire = wire_options(args);
  if (!wire) return usage_error(self, wire.error());
  if (args.positional.size() < 2) return usage_error(self, "give a link URL and a COMMAND");
  Result<long> timeout = option_integer(args, "--timeout", 1000, 1, 60000);
  if (!timeout) return usage_error(self, timeout.error());
  Result<long> retries = option_integer(args, "--retries", 2, 0, 10);
  if (!retries) return usage_error(self, retries.error());
  Result<long> connect_timeout = option_integer(args, "--connect-timeout", 3000, 1, 60000);
  if (!connect_timeout) return usage_error(self, connect_timeout.error());
  Result<Request> request = build_request(args, wire->codec);
  if (!request) return usage_error(self, request.error());

  const std::string& url = args.positional[0];
  Result<std::unique_ptr<transport::Transport>> link = transport::make_transport(url);
  if (!link) return usage_error(self, link.error());

  session::SessionOptions options;
  options.codec = wire->codec;
  options.crc_coverage = wire->crc_coverage;
  options.ack_timeout = std::chrono::milliseconds(timeout.value());
  options.retries = static_cast<int>(retries.value());
  // Declared before the session: the session's last state callback (kClosed, on destruction)
  // still reaches it.
  ConnectionWaiter waiter;
  session::Session session(std::move(link.value()), options);
  session.on_link_state(
      [&](transport::LinkState state, const std::string& reason) { waiter.update(state, reason); });
  const Status started = session.start();
  if (!started) {
    std::fprintf(stderr, "k40t send: %s\n", started.message().c_str());
    return kExitFailed;
  }
  if (!waiter.wait(std::chrono::milliseconds(connect_timeout.value()), session)) {
    if (session.stats().link.device_busy) {
      std::fprintf(stderr, "k40t send: %s\n", waiter.last_reason().c_str());
    } else {
      std::fprintf(stderr, "k40t send: %s: not connected after %ld ms%s%s\n", url.c_str(),
                   connect_timeout.value(), waiter.last_reason().empty() ? "" : ": ",
                   waiter.last_reason().c_str());
    }
    return kExitFailed;
  }

  const session::AckResult result =
      session.request_raw(request->id, request->payload.data(), request->payload.size);
  if (result.received) {
    const protocol::MessageId ack_id = protocol::ack_id_of(request->id);
    const protocol::MessageInfo* ack_info = protocol::find_message(ack_id);
    std::printf(
        "%s %s\n", ack_info ? ack_info->name : id_text(ack_id).c_str(),
        payload_summary(ack_id, result.payload.data(), result.payload.size(), session.codec())
            .c_str());
  }
  if (!result.ok()) {
    std::fprintf(stderr, "k40t send: %s\n", result.message.c_str());
    return kExitFailed;
  }
  return kExitOk;
}

}  // namespace

const Command& send_command() {
  static const Command command{
      "send",
      "send URL COMMAND [name=value ...] [options]",
      "send one request, print the decoded ACK; exit 1 on NACK or timeout",
      "Sends one request over the link URL and waits for its ACK. COMMAND is a request name\n"
      "from 'k40t list' with its fields as name=value arguments (units in the names; fields\n"
      "not given keep their defaults; 'k40t list --fields' shows them), or a hex id such as\n"
      "0x000400 with --payload HEX. Arguments are validated before anything is sent.\n"
      "Prints the decoded ACK and exits 0 when the pod answers OK; on a refusal (NACK) or\n"
      "no answer after the retries, prints the reason on stderr and exits 1.\n\n"
      "example: k40t send serial:///dev/ttyUSB0 laser_range enable=1",
      {{"--payload", "HEX", "raw payload bytes instead of name=value fields"},
       {"--timeout", "MS", "ACK timeout per attempt (default 1000)"},
       {"--retries", "N", "extra attempts after a timeout (default 2)"},
       {"--connect-timeout", "MS", "how long to wait for the link (default 3000)"},
       kCrcCoverageOption,
       kAckByteOrderOption},
      &run_send};
  return command;
}

}  // namespace k40t::tool
