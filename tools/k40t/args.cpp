#include <cerrno>
#include <cstdio>
#include <cstdlib>

#include "command.h"

namespace k40t::tool {

namespace {
const OptionSpec* find_spec(const std::vector<OptionSpec>& specs, const std::string& name) {
  for (const OptionSpec& s : specs) {
    if (name == s.name) return &s;
  }
  return nullptr;
}
}  // namespace

Result<ParsedArgs> parse_args(const std::vector<std::string>& args,
                              const std::vector<OptionSpec>& specs) {
  ParsedArgs parsed;
  bool options_ended = false;
  for (size_t i = 0; i < args.size(); ++i) {
    const std::string& arg = args[i];
    if (options_ended || arg.size() < 2 || arg[0] != '-') {
      parsed.positional.push_back(arg);
      continue;
    }
    if (arg == "--") {
      options_ended = true;
      continue;
    }
    if (arg == "-h" || arg == "--help") {
      parsed.help = true;
      continue;
    }
    const size_t equals = arg.find('=');
    const std::string name = arg.substr(0, equals);
    const OptionSpec* spec = find_spec(specs, name);
    if (spec == nullptr) return Result<ParsedArgs>::fail("unknown option '" + name + "'");
    if (spec->value == nullptr) {
      if (equals != std::string::npos)
        return Result<ParsedArgs>::fail("option " + name + " takes no value");
      parsed.flags.insert(name);
      continue;
    }
    std::string value;
    if (equals != std::string::npos) {
      value = arg.substr(equals + 1);
    } else if (i + 1 < args.size()) {
      value = args[++i];
    } else {
      return Result<ParsedArgs>::fail("option " + name + " needs a value (" + spec->value + ")");
    }
    if (parsed.options.count(name) != 0)
      return Result<ParsedArgs>::fail("option " + name + " given twice");
    parsed.options[name] = value;
  }
  return parsed;
}

void print_command_help(const Command& command) {
  std::printf("usage: k40t %s\n\n%s\n", command.synopsis, command.description);
  std::printf("\noptions:\n");
  for (const OptionSpec& o : command.options) {
    std::string left = std::string(o.name) + (o.value ? std::string(" ") + o.value : "");
    std::printf("  %-28s %s\n", left.c_str(), o.help);
  }
  std::printf("  %-28s %s\n", "-h, --help", "this help");
}

int usage_error(const Command& command, const std::string& message) {
  std::fprintf(stderr, "k40t %s: %s\nTry 'k40t %s --help'.\n", command.name, message.c_str(),
               command.name);
  return kExitUsage;
}

const OptionSpec kCrcCoverageOption = {
    "--crc-coverage", "auto|header_excluded|whole_frame",
    "bytes the checksum covers (docs/protocol/decisions.md#a1; default auto)"};
const OptionSpec kAckByteOrderOption = {
    "--ack-byte-order", "big|little|auto",
    "byte order of ACK fields (docs/protocol/decisions.md#a2; default big; auto: big until an ACK "
    "shows the pod's)"};

Result<WireOptions> wire_options(const ParsedArgs& args) {
  WireOptions wire;
  const auto coverage = args.options.find(kCrcCoverageOption.name);
  if (coverage != args.options.end()) {
    Result<protocol::CrcCoverage> parsed = protocol::parse_crc_coverage(coverage->second);
    if (!parsed) return Result<WireOptions>::fail("--crc-coverage: " + parsed.error());
    wire.crc_coverage = parsed.value();
  }
  const auto order = args.options.find(kAckByteOrderOption.name);
  if (order != args.options.end()) {
    // auto: the link's ACKs lock it (protocol/ack_order_setting.h), as in the driver.
    const Status parsed = protocol::parse_ack_byte_order(order->second, wire.codec);
    if (!parsed) return Result<WireOptions>::fail("--ack-byte-order: " + parsed.message());
  }
  return wire;
}

Result<long> option_integer(const ParsedArgs& args, const std::string& option, long fallback,
                            long lo, long hi) {
  const auto found = args.options.find(option);
  if (found == args.options.end()) return fallback;
  const std::string& text = found->second;
  errno = 0;
  char* end = nullptr;
  const long value = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || *end != '\0' || errno == ERANGE || value < lo || value > hi) {
    return Result<long>::fail(option + " must be an integer " + std::to_string(lo) + ".." +
                              std::to_string(hi) + ", got '" + text + "'");
  }
  return value;
}

}  // namespace k40t::tool
