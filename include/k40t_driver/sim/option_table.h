// Command lines of the simulators (k40t_sim, skyport_sim) as tables of options: each option's
// name, argument, help text and how it changes the options struct. One parser and one usage
// formatter for all of them. Arguments roslaunch adds (__name:=..., __log:=...) are skipped;
// "--name=value" and "--name value" both work.
#pragma once

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/protocol/result.h"

namespace k40t::sim {

template <class Options>
struct OptionSpec {
  const char* name;
  const char* argument;  // nullptr for flags
  const char* help;
  std::function<Status(Options& options, const std::string& option, const std::string& value)>
      apply;
};

// One argument split into its option name and the value given with '=' (if any).
struct SplitArgument {
  std::string name;
  std::optional<std::string> inline_value;
};
SplitArgument split_argument(const std::string& arg);
bool is_ros_argument(const std::string& arg);

// "  --name ARG   help..." with the help wrapped and aligned in one column.
std::string format_option(const char* name, const char* argument, const char* help);

template <class Options>
Status parse_option_table(const std::vector<OptionSpec<Options>>& table,
                          const std::vector<std::string>& args, Options& options) {
  for (size_t i = 0; i < args.size(); ++i) {
    if (is_ros_argument(args[i])) continue;
    const SplitArgument arg = split_argument(args[i]);
    const OptionSpec<Options>* spec = nullptr;
    for (const OptionSpec<Options>& candidate : table) {
      if (arg.name == candidate.name) spec = &candidate;
    }
    if (!spec) return Status::fail("unknown argument '" + args[i] + "' (see --help)");
    std::string value;
    if (spec->argument) {
      if (arg.inline_value) {
        value = *arg.inline_value;
      } else if (i + 1 < args.size()) {
        value = args[++i];
      } else {
        return Status::fail(arg.name + ": missing " + spec->argument);
      }
    } else if (arg.inline_value) {
      return Status::fail(arg.name + ": takes no value");
    }
    const Status applied = spec->apply(options, arg.name, value);
    if (!applied) return applied;
  }
  return Status::ok();
}

template <class Options>
std::string option_table_usage(const std::vector<OptionSpec<Options>>& table) {
  std::string out;
  for (const OptionSpec<Options>& spec : table)
    out += format_option(spec.name, spec.argument, spec.help);
  return out;
}

}  // namespace k40t::sim
