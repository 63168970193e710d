// The k40t tool's subcommands and their shared argument handling. Each subcommand lives in its
// own cmd_<name>.cpp and is listed in main.cpp's table.
//
// Exit codes: 0 success, 1 the operation failed (NACK, timeout, unreadable input, no link),
// 2 bad arguments (message on stderr, with a pointer to --help).
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/result.h"

namespace k40t::tool {

constexpr int kExitOk = 0;
constexpr int kExitFailed = 1;
constexpr int kExitUsage = 2;

struct OptionSpec {
  const char* name;   // "--timeout"
  const char* value;  // placeholder shown in help ("MS"), or nullptr for a flag
  const char* help;
};

struct ParsedArgs {
  std::map<std::string, std::string> options;  // "--timeout" -> "500"
  std::set<std::string> flags;                 // "--fields"
  std::vector<std::string> positional;
  bool help = false;  // -h / --help seen
  bool has(const std::string& option) const {
    return options.count(option) != 0 || flags.count(option) != 0;
  }
};

struct Command {
  const char* name;
  const char* synopsis;     // "decode [--hex HEX | FILE | -]"
  const char* summary;      // one line for the tool's help
  const char* description;  // paragraphs for the subcommand's help
  std::vector<OptionSpec> options;
  int (*run)(const Command& self, const ParsedArgs& args);
};

// --opt VALUE, --opt=VALUE, flags, "--" ends options, "-" is positional. Unknown options fail.
Result<ParsedArgs> parse_args(const std::vector<std::string>& args,
                              const std::vector<OptionSpec>& specs);

void print_command_help(const Command& command);
// Prints "k40t <cmd>: <message>" and the --help hint on stderr; returns kExitUsage.
int usage_error(const Command& command, const std::string& message);

// The wire options every link-facing command takes (docs/protocol/decisions.md#a1, A2).
struct WireOptions {
  protocol::CrcCoverage crc_coverage = protocol::CrcCoverage::kAuto;
  protocol::CodecOptions codec;
};
extern const OptionSpec kCrcCoverageOption;
extern const OptionSpec kAckByteOrderOption;
Result<WireOptions> wire_options(const ParsedArgs& args);

// Strict number parsing for option values: "--timeout must be an integer 1..60000, got 'x'".
Result<long> option_integer(const ParsedArgs& args, const std::string& option, long fallback,
                            long lo, long hi);

// The subcommands (cmd_*.cpp).
const Command& decode_command();
const Command& monitor_command();
const Command& send_command();
const Command& list_command();
const Command& probe_command();
// Runs `program` of the ROS build with `arguments` in place of this process (ros_program.cpp);
// returns only when it cannot, after saying why (`command`: the subcommand, for the message).
int run_ros_program(const std::string& program, const std::string& command, const char* argv0,
                    const std::vector<std::string>& arguments);
// `k40t bag ...`: runs k40t_bag with the arguments after "bag".
int run_bag_program(int argc, char** argv);
// The argv[0] the tool was started with (for run_ros_program).
const char* program_path();
void set_program_path(const char* argv0);

}  // namespace k40t::tool
