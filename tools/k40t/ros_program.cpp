// The subcommands that need ROS, which this ROS-free tool does not link, run a program of the ROS
// build: `k40t bag ARGS` runs `k40t_bag ARGS` (rosbag), `k40t monitor ros:///NS` runs
// `k40t_topic_monitor NS` (roscpp). Looked for beside this program (as invoked: rosrun's
// devel/lib/k40t_driver), beside the real file (an installed package), in the source tree's devel
// space (build/core/bin/k40t), then on PATH.
#include <limits.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "command.h"

namespace k40t::tool {

namespace {

const char* g_program_path = "k40t";

std::string directory_of(const std::string& path) {
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

std::vector<std::string> candidates(const char* argv0, const std::string& program) {
  std::vector<std::string> out;
  const std::string invoked = directory_of(argv0);
  if (!invoked.empty()) out.push_back(invoked + "/" + program);
  char real[PATH_MAX];
  const ssize_t size = ::readlink("/proc/self/exe", real, sizeof(real) - 1);
  if (size > 0) {
    real[size] = '\0';
    const std::string dir = directory_of(real);
    out.push_back(dir + "/" + program);
    out.push_back(dir + "/../../../devel/lib/k40t_driver/" + program);  // <root>/build/core/bin
  }
  return out;
}

}  // namespace

const char* program_path() {
  return g_program_path;
}

void set_program_path(const char* argv0) {
  g_program_path = argv0;
}

int run_ros_program(const std::string& program, const std::string& command, const char* argv0,
                    const std::vector<std::string>& arguments) {
  std::vector<char*> args{const_cast<char*>(program.c_str())};
  for (const std::string& argument : arguments) args.push_back(const_cast<char*>(argument.c_str()));
  args.push_back(nullptr);
  for (const std::string& path : candidates(argv0, program)) {
    if (::access(path.c_str(), X_OK) == 0) ::execv(path.c_str(), args.data());
  }
  ::execvp(program.c_str(), args.data());
  std::fprintf(stderr,
               "k40t %s: cannot run %s (%s): it comes with the ROS build (scripts/build.sh ros); "
               "run `rosrun k40t_driver k40t %s ...` or put devel/lib/k40t_driver on PATH\n",
               command.c_str(), program.c_str(), std::strerror(errno), command.c_str());
  return kExitFailed;
}

int run_bag_program(int argc, char** argv) {
  return run_ros_program("k40t_bag", "bag", argv[0],
                         std::vector<std::string>(argv + 2, argv + argc));  // what follows "bag"
}

}  // namespace k40t::tool
