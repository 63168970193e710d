#include "k40t_driver/sim/control_server.h"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <sys/un.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <map>
#include <vector>

namespace k40t::sim {

namespace {

Status fail(const std::string& endpoint, const std::string& what) {
  return Status::fail("control socket " + endpoint + ": " + what + ": " + std::strerror(errno));
}

// "5761", "tcp:5761", "tcp:127.0.0.1:5761" -> port; -1 when not a TCP endpoint or malformed.
int parse_tcp_port(const std::string& endpoint, std::string* error) {
  std::string rest = endpoint;
  if (rest.rfind("tcp:", 0) == 0) rest = rest.substr(4);
  const std::string loopback = "127.0.0.1:";
  if (rest.rfind(loopback, 0) == 0) rest = rest.substr(loopback.size());
  if (rest.empty() || rest.find_first_not_of("0123456789") != std::string::npos) {
    *error = "expected PORT, tcp:PORT, tcp:127.0.0.1:PORT or unix:PATH, got '" + endpoint + "'";
    return -1;
  }
  const long port = std::strtol(rest.c_str(), nullptr, 10);
  if (port > 65535) {
    *error = "port must be 0..65535, got " + rest;
    return -1;
  }
  return static_cast<int>(port);
}

}  // namespace

ControlServer::~ControlServer() {
  stop();
}

Status ControlServer::start(const std::string& endpoint, Handler handler) {
  if (thread_.joinable()) return Status::fail("control socket: already started on " + endpoint_);
  handler_ = std::move(handler);
  endpoint_ = endpoint;
  if (endpoint.rfind("unix:", 0) == 0) {
    unix_path_ = endpoint.substr(5);
    sockaddr_un addr{};
    if (unix_path_.empty() || unix_path_.size() >= sizeof(addr.sun_path)) {
      return Status::fail("control socket " + endpoint + ": the path must be 1.." +
                          std::to_string(sizeof(addr.sun_path) - 1) + " bytes");
    }
    listen_fd_ = ::socket(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (listen_fd_ < 0) return fail(endpoint, "socket");
    addr.sun_family = AF_UNIX;
    std::memcpy(addr.sun_path, unix_path_.c_str(), unix_path_.size());
    ::unlink(unix_path_.c_str());
    if (::bind(listen_fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
      const Status status = fail(endpoint, "bind");
      stop();
      return status;
    }
  } else {
    std::string error;
    const int port = parse_tcp_port(endpoint, &error);
    if (port < 0) return Status::fail("control socket: " + error);
    listen_fd_ = ::socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (listen_fd_ < 0) return fail(endpoint, "socket");
    const int yes = 1;
    ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t size = sizeof addr;
    if (::bind(listen_fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0 ||
        ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&addr), &size) != 0) {
      const Status status = fail(endpoint, "bind");
      stop();
      return status;
    }
    port_ = ntohs(addr.sin_port);
  }
  if (::listen(listen_fd_, 4) != 0 || ::pipe2(wake_pipe_, O_CLOEXEC) != 0) {
    const Status status = fail(endpoint, "listen");
    stop();
    return status;
  }
  thread_ = std::thread([this] { serve(); });
  return Status::ok();
}

void ControlServer::stop() {
  if (thread_.joinable()) {
    const char byte = 0;
    (void)!::write(wake_pipe_[1], &byte, 1);
    thread_.join();
  }
  for (int* fd : {&listen_fd_, &wake_pipe_[0], &wake_pipe_[1]}) {
    if (*fd >= 0) ::close(*fd);
    *fd = -1;
  }
  if (!unix_path_.empty()) ::unlink(unix_path_.c_str());
  unix_path_.clear();
}

void ControlServer::serve() {
  std::map<int, std::string> clients;  // fd -> partial line
  for (;;) {
    std::vector<pollfd> fds = {{wake_pipe_[0], POLLIN, 0}, {listen_fd_, POLLIN, 0}};
    for (const auto& client : clients) fds.push_back({client.first, POLLIN, 0});
    if (::poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      break;
    }
    if (fds[0].revents) break;
    if (fds[1].revents & POLLIN) {
      const int fd = ::accept4(listen_fd_, nullptr, nullptr, SOCK_CLOEXEC);
      if (fd >= 0) clients[fd];
    }
    for (size_t i = 2; i < fds.size(); ++i) {
      if (!fds[i].revents) continue;
      const int fd = fds[i].fd;
      char buffer[512];
      const ssize_t n = ::read(fd, buffer, sizeof buffer);
      if (n <= 0) {
        ::close(fd);
        clients.erase(fd);
        continue;
      }
      std::string& pending = clients[fd];
      pending.append(buffer, static_cast<size_t>(n));
      for (size_t end; (end = pending.find('\n')) != std::string::npos;) {
        std::string line = pending.substr(0, end);
        pending.erase(0, end + 1);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        const std::string reply = handler_(line) + "\n";
        (void)!::send(fd, reply.data(), reply.size(), MSG_NOSIGNAL);
      }
      if (pending.size() > 4096) pending.clear();  // no newline in sight: not our protocol
    }
  }
  for (const auto& client : clients) ::close(client.first);
}

}  // namespace k40t::sim
