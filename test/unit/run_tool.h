// Runs a built command-line program (K40T_BINARY_DIR) through the shell and captures its exit
// code, stdout and stderr, for tests of the k40t tool.
#pragma once

#include <string>

namespace k40t::test {

struct ToolRun {
  int exit_code = -1;
  std::string out;
  std::string err;
};

// `arguments` is appended to the command line as is (quote with single quotes where needed);
// `stdin_text`, if not empty, is fed on stdin.
ToolRun run_k40t(const std::string& arguments, const std::string& stdin_text = "");
// Runs any shell command the same way (scripts).
ToolRun run_shell(const std::string& command);

std::string k40t_path();
// A fresh path under the temp directory, unique per process and call.
std::string temp_path(const std::string& stem);
std::string read_file(const std::string& path);

}  // namespace k40t::test
