// k40t: the K40T pod's command-line tool (ROS-free). Subcommands: decode, monitor, send, list,
// probe; bag runs the ROS build's k40t_bag (ros_program.cpp).
#include <cstdio>
#include <string>
#include <vector>

#include "command.h"

namespace k40t::tool {
namespace {

std::vector<const Command*> commands() {
  return {&decode_command(), &monitor_command(), &send_command(), &list_command(),
          &probe_command()};
}

void print_tool_help() {
  std::printf(
      "usage: k40t COMMAND [arguments]\n\n"
      "The K40T gimbal pod's protocol on the command line: decode captures, watch a link,\n"
      "send one request.\n\ncommands:\n");
  for (const Command* c : commands()) std::printf("  %-9s %s\n", c->name, c->summary);
  std::printf("  %-9s %s\n", "bag", "recorded flights -> bags of the decoded topics (ROS build)");
  std::printf(
      "\n'k40t COMMAND --help' explains each. Links are URLs: serial:///dev/ttyUSB0?baud=115200,\n"
      "udp://HOST:PORT, tcp://HOST:PORT, pty:///tmp/k40t_pod ...\n"
      "Exit codes: 0 success, 1 the operation failed, 2 bad arguments.\n");
}

int run(int argc, char** argv) {
  set_program_path(argv[0]);
  if (argc < 2) {
    std::fprintf(stderr, "k40t: missing COMMAND\nTry 'k40t --help'.\n");
    return kExitUsage;
  }
  const std::string name = argv[1];
  if (name == "--help" || name == "-h" || name == "help") {
    print_tool_help();
    return kExitOk;
  }
  if (name == "bag") return run_bag_program(argc, argv);  // the ROS build's k40t_bag
  for (const Command* command : commands()) {
    if (name != command->name) continue;
    Result<ParsedArgs> args =
        parse_args(std::vector<std::string>(argv + 2, argv + argc), command->options);
    if (!args) return usage_error(*command, args.error());
    if (args->help) {
      print_command_help(*command);
      return kExitOk;
    }
    return command->run(*command, args.value());
  }
  std::string known;
  for (const Command* c : commands()) known += std::string(known.empty() ? "" : ", ") + c->name;
  std::fprintf(stderr, "k40t: unknown command '%s' (commands: %s)\nTry 'k40t --help'.\n",
               name.c_str(), known.c_str());
  return kExitUsage;
}

}  // namespace
}  // namespace k40t::tool

int main(int argc, char** argv) {
  return k40t::tool::run(argc, argv);
}
