// tcp://host:port (client) and tcp-server://addr:port (one client at a time, newest wins).
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>

#include <cerrno>
#include <chrono>
#include <string>

#include "links.h"
#include "socket_address.h"

namespace k40t::transport {
namespace {

constexpr std::chrono::milliseconds kConnectTimeout{5000};
constexpr int kListenBacklog = 4;

// Frames are small and latency matters more than packet count.
void set_no_delay(int fd) {
  const int on = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &on, sizeof on);
}

// Both ends send with MSG_NOSIGNAL: a reset peer must give EPIPE, not kill the process.
class TcpLink : public LinkDriver {
 public:
  ssize_t transmit(int fd, const uint8_t* data, size_t size) override {
    return ::send(fd, data, size, MSG_NOSIGNAL);
  }
};

class TcpClientLink : public TcpLink {
 public:
  explicit TcpClientLink(HostPort server) : server_(std::move(server)) {}

  Result<int> connect(const Waiter& waiter) override {
    using R = Result<int>;
    auto address = resolve_address(server_.host, server_.port, SOCK_STREAM, false);
    if (!address) return R::fail(address.error());
    auto fd = open_socket(*address, SOCK_STREAM);
    if (!fd) return R::fail(fd.error());
    const std::string name = address->text();
    if (::connect(fd->get(), address->get(), address->length) < 0 && errno != EINPROGRESS) {
      return R::fail("cannot connect to " + name + ": " + errno_text(errno));
    }
    switch (waiter.wait(fd->get(), POLLOUT, kConnectTimeout)) {
      case Waiter::Outcome::kStopped:
        return R::fail("stopped while connecting to " + name);
      case Waiter::Outcome::kTimeout:
        return R::fail("no answer from " + name + " within " +
                       std::to_string(kConnectTimeout.count()) + " ms");
      case Waiter::Outcome::kReady:
        break;
    }
    int error = 0;
    socklen_t length = sizeof error;
    if (::getsockopt(fd->get(), SOL_SOCKET, SO_ERROR, &error, &length) < 0) error = errno;
    if (error != 0) return R::fail("cannot connect to " + name + ": " + errno_text(error));
    set_no_delay(fd->get());
    socket_ = std::move(fd).value();
    return socket_.get();
  }

  void disconnect() override { socket_.reset(); }

 private:
  const HostPort server_;
  UniqueFd socket_;
};

class TcpServerLink : public TcpLink {
 public:
  explicit TcpServerLink(HostPort address) : address_(std::move(address)) {}

  // Waits for the next client (the listening socket persists across clients).
  Result<int> connect(const Waiter& waiter) override {
    using R = Result<int>;
    if (!listener_.valid()) {
      if (Status s = listen(); !s) return R::fail(s.message());
    }
    while (true) {
      if (waiter.wait(listener_.get(), POLLIN, std::chrono::milliseconds(-1)) ==
          Waiter::Outcome::kStopped) {
        return R::fail("stopped while waiting for a client on " + listening_on_);
      }
      SocketAddress peer;
      peer.length = sizeof peer.storage;
      UniqueFd client(::accept4(listener_.get(), reinterpret_cast<sockaddr*>(&peer.storage),
                                &peer.length, SOCK_NONBLOCK | SOCK_CLOEXEC));
      if (!client.valid()) {
        // The pending client gave up before we took it: keep waiting for another.
        if (errno == EAGAIN || errno == EWOULDBLOCK || errno == ECONNABORTED || errno == EINTR) {
          continue;
        }
        return R::fail("accept on " + listening_on_ + " failed: " + errno_text(errno));
      }
      set_no_delay(client.get());
      client_name_ = peer.text();
      client_ = std::move(client);
      return client_.get();
    }
  }

  void disconnect() override { client_.reset(); }
  void shutdown() override {
    client_.reset();
    listener_.reset();
  }

  int preempt_fd() const override { return listener_.get(); }
  std::string preempt_reason() const override { return "a new client replaces " + client_name_; }

 private:
  Status listen() {
    auto address = resolve_address(address_.host, address_.port, SOCK_STREAM, true);
    if (!address) return address.status();
    auto fd = open_socket(*address, SOCK_STREAM);
    if (!fd) return fd.status();
    if (Status s = bind_socket(fd->get(), *address, true); !s) return s;
    if (::listen(fd->get(), kListenBacklog) < 0) {
      return Status::fail("cannot listen on " + address->text() + ": " + errno_text(errno));
    }
    listening_on_ = address->text();
    listener_ = std::move(fd).value();
    return Status::ok();
  }

  const HostPort address_;
  UniqueFd listener_;
  UniqueFd client_;
  std::string listening_on_;
  std::string client_name_;
};

}  // namespace

LinkResult make_tcp_client_link(const DeviceUrl& url) {
  return LinkResult(std::make_unique<TcpClientLink>(HostPort{url.host, url.port}));
}

LinkResult make_tcp_server_link(const DeviceUrl& url) {
  return LinkResult(std::make_unique<TcpServerLink>(HostPort{url.host, url.port}));
}

}  // namespace k40t::transport
