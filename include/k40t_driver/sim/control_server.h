// The control socket of the simulator: a line-oriented server on a local endpoint, one reply
// line per command line (see control_commands.h for the language). Endpoints:
//   PORT | tcp:PORT | tcp:127.0.0.1:PORT   TCP on the loopback interface only
//   unix:/path/to/socket                  a Unix-domain stream socket (the file is replaced)
// Several clients may be connected at once; each line is handled on the server's thread.
#pragma once

#include <atomic>
#include <functional>
#include <string>
#include <thread>

#include "k40t_driver/protocol/result.h"

namespace k40t::sim {

class ControlServer {
 public:
  using Handler = std::function<std::string(const std::string& line)>;

  ControlServer() = default;
  ~ControlServer();
  ControlServer(const ControlServer&) = delete;
  ControlServer& operator=(const ControlServer&) = delete;

  // Binds and starts serving; fails naming the endpoint and the reason.
  Status start(const std::string& endpoint, Handler handler);
  void stop();
  // For tcp endpoints with port 0: the port the system chose.
  int port() const { return port_; }
  const std::string& endpoint() const { return endpoint_; }

 private:
  void serve();

  Handler handler_;
  std::string endpoint_;
  std::string unix_path_;
  int listen_fd_ = -1;
  int wake_pipe_[2] = {-1, -1};
  int port_ = 0;
  std::thread thread_;
};

}  // namespace k40t::sim
