// k40t bag: offline decoding of recorded flights needs rosbag, which this ROS-free tool does not
// link; the ROS build's k40t_bag program does the work, and `k40t bag ARGS` runs `k40t_bag ARGS`.
// Looked for beside this program (as invoked: rosrun's devel/lib/k40t_driver), beside the real
// file (an installed package), in the source tree's devel space (build/core/bin/k40t), then on
// PATH.
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

constexpr const char* kProgram = "k40t_bag";

std::string directory_of(const std::string& path) {
  const size_t slash = path.rfind('/');
  return slash == std::string::npos ? std::string() : path.substr(0, slash);
}

std::vector<std::string> candidates(const char* argv0) {
  std::vector<std::string> out;
  const std::string invoked = directory_of(argv0);
  if (!invoked.empty()) out.push_back(invoked + "/" + kProgram);
  char real[PATH_MAX];
  const ssize_t size = ::readlink("/proc/self/exe", real, sizeof(real) - 1);
  if (size > 0) {
    real[size] = '\0';
    const std::string dir = directory_of(real);
    out.push_back(dir + "/" + kProgram);
    out.push_back(dir + "/../../../devel/lib/k40t_driver/" + kProgram);  // <root>/build/core/bin
  }
  return out;
}

}  // namespace

int run_bag_program(int argc, char** argv) {
  std::vector<char*> args{const_cast<char*>(kProgram)};
  for (int i = 2; i < argc; ++i) args.push_back(argv[i]);  // what follows "bag"
  args.push_back(nullptr);
  for (const std::string& path : candidates(argv[0])) {
    if (::access(path.c_str(), X_OK) == 0) ::execv(path.c_str(), args.data());
  }
  ::execvp(kProgram, args.data());
  std::fprintf(stderr,
               "k40t bag: cannot run %s (%s): it comes with the ROS build (scripts/build.sh ros); "
               "run `rosrun k40t_driver k40t bag ...` or put devel/lib/k40t_driver on PATH\n",
               kProgram, std::strerror(errno));
  return kExitFailed;
}

}  // namespace k40t::tool
