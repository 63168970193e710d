// Helpers of the video tests: the standalone simulated stream as a child process (so a test can
// freeze it with SIGSTOP, as a hung pod would look), and waiting for a grabber.
#pragma once

#include <signal.h>
#include <sys/types.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <functional>
#include <string>
#include <thread>
#include <vector>

namespace k40t::video::testing {

// k40t_video_sim (the unit tests': K40T_BINARY_DIR's; or `program`) started with `args` (plus
// --port 0); url() is what it printed it serves. Also used by the passthrough rostest.
class SimStreamProcess {
 public:
#ifdef K40T_BINARY_DIR
  explicit SimStreamProcess(std::vector<std::string> args)
      : SimStreamProcess(std::string(K40T_BINARY_DIR) + "/k40t_video_sim", std::move(args)) {}
#endif
  SimStreamProcess(const std::string& program, std::vector<std::string> args) {
    int out[2];
    if (pipe(out) != 0) return;
    pid_ = fork();
    if (pid_ == 0) {
      dup2(out[1], STDOUT_FILENO);
      close(out[0]);
      close(out[1]);
      std::vector<std::string> all{program, "--port", "0"};
      all.insert(all.end(), args.begin(), args.end());
      std::vector<char*> argv;
      for (auto& a : all) argv.push_back(a.data());
      argv.push_back(nullptr);
      execv(program.c_str(), argv.data());
      _exit(127);
    }
    close(out[1]);
    FILE* stream = fdopen(out[0], "r");
    char line[256];
    if (stream && fgets(line, sizeof line, stream)) {
      const std::string text(line);
      const size_t at = text.find("rtsp://");
      if (at != std::string::npos) url_ = text.substr(at, text.find_last_not_of("\r\n") + 1 - at);
    }
    if (stream) fclose(stream);
  }
  ~SimStreamProcess() {
    if (pid_ > 0) {
      // SIGTERM first, so a frozen server ends as soon as it runs again: left to run on with the
      // connections its clients dropped meanwhile, gst-rtsp-server floods stderr with GLib
      // criticals until it is stopped.
      kill(pid_, SIGTERM);
      kill(pid_, SIGCONT);
      waitpid(pid_, nullptr, 0);
    }
  }
  const std::string& url() const { return url_; }
  void freeze() { kill(pid_, SIGSTOP); }

 private:
  pid_t pid_ = -1;
  std::string url_;
};

// Polls `condition` every 10 ms for up to `timeout`; the time it took, or nothing.
inline std::optional<std::chrono::duration<double>> wait_until(
    const std::function<bool()>& condition, std::chrono::duration<double> timeout) {
  const auto start = std::chrono::steady_clock::now();
  while (std::chrono::steady_clock::now() - start < timeout) {
    if (condition()) return std::chrono::steady_clock::now() - start;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return std::nullopt;
}

}  // namespace k40t::video::testing
