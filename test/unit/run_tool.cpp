#include "run_tool.h"

#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace k40t::test {

std::string k40t_path() {
  return std::string(K40T_BINARY_DIR) + "/k40t";
}

std::string temp_path(const std::string& stem) {
  static std::atomic<int> counter{0};
  const char* dir = std::getenv("TMPDIR");
  return std::string(dir && *dir ? dir : "/tmp") + "/k40t_test_" + std::to_string(getpid()) + "_" +
         std::to_string(counter++) + "_" + stem;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  return text.str();
}

ToolRun run_shell(const std::string& command) {
  const std::string err_path = temp_path("stderr");
  ToolRun run;
  std::FILE* pipe = popen((command + " 2>'" + err_path + "'").c_str(), "r");
  if (pipe == nullptr) return run;
  char buffer[4096];
  size_t n = 0;
  while ((n = std::fread(buffer, 1, sizeof(buffer), pipe)) > 0) run.out.append(buffer, n);
  const int status = pclose(pipe);
  run.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  run.err = read_file(err_path);
  std::remove(err_path.c_str());
  return run;
}

ToolRun run_k40t(const std::string& arguments, const std::string& stdin_text) {
  std::string command = "'" + k40t_path() + "' " + arguments;
  std::string in_path;
  if (!stdin_text.empty()) {
    in_path = temp_path("stdin");
    std::ofstream(in_path) << stdin_text;
    command += " <'" + in_path + "'";
  }
  ToolRun run = run_shell(command);
  if (!in_path.empty()) std::remove(in_path.c_str());
  return run;
}

}  // namespace k40t::test
