// udp://host:port[?bind=addr:port] (client) and udp-server://addr:port (replies to the last peer).
#include <sys/socket.h>

#include <cerrno>
#include <mutex>
#include <optional>
#include <string>

#include "links.h"
#include "socket_address.h"

namespace k40t::transport {
namespace {

// A bound, non-blocking datagram socket.
Result<UniqueFd> open_bound_socket(const HostPort& local) {
  auto address = resolve_address(local.host, local.port, SOCK_DGRAM, true);
  if (!address) return Result<UniqueFd>::fail(address.error());
  auto fd = open_socket(*address, SOCK_DGRAM);
  if (!fd) return fd;
  if (Status s = bind_socket(fd->get(), *address, false); !s) return Result<UniqueFd>(s);
  return fd;
}

class UdpLink : public LinkDriver {
 public:
  bool is_datagram() const override { return true; }
  // An ICMP "port unreachable" for an earlier datagram: the peer is not up yet, nothing to reset.
  bool is_transient_error(int error) const override { return error == ECONNREFUSED; }
  void disconnect() override { socket_.reset(); }

 protected:
  UniqueFd socket_;
};

class UdpClientLink : public UdpLink {
 public:
  UdpClientLink(HostPort remote, std::optional<HostPort> bind)
      : remote_name_(std::move(remote)), bind_(std::move(bind)) {}

  Result<int> connect(const Waiter& /*waiter*/) override {
    using R = Result<int>;
    auto remote = resolve_address(remote_name_.host, remote_name_.port, SOCK_DGRAM, false);
    if (!remote) return R::fail(remote.error());
    auto fd = bind_ ? open_bound_socket(*bind_) : open_socket(*remote, SOCK_DGRAM);
    if (!fd) return R::fail(fd.error());
    remote_ = *remote;
    socket_ = std::move(fd).value();
    return socket_.get();
  }

  // Unconnected socket + sendto: replies are accepted whatever source address the peer uses.
  ssize_t transmit(int fd, const uint8_t* data, size_t size) override {
    return ::sendto(fd, data, size, MSG_NOSIGNAL, remote_.get(), remote_.length);
  }

 private:
  const HostPort remote_name_;
  const std::optional<HostPort> bind_;
  SocketAddress remote_;
};

class UdpServerLink : public UdpLink {
 public:
  explicit UdpServerLink(HostPort local) : local_(std::move(local)) {}

  Result<int> connect(const Waiter& /*waiter*/) override {
    auto fd = open_bound_socket(local_);
    if (!fd) return Result<int>::fail(fd.error());
    socket_ = std::move(fd).value();
    return socket_.get();
  }

  void disconnect() override {
    UdpLink::disconnect();
    std::lock_guard<std::mutex> lock(peer_mutex_);
    peer_ = SocketAddress();
  }

  ssize_t receive(int fd, uint8_t* buffer, size_t size) override {
    SocketAddress from;
    from.length = sizeof from.storage;
    const ssize_t n =
        ::recvfrom(fd, buffer, size, 0, reinterpret_cast<sockaddr*>(&from.storage), &from.length);
    if (n >= 0) {
      std::lock_guard<std::mutex> lock(peer_mutex_);
      peer_ = from;
    }
    return n;
  }

  Status can_send() const override {
    std::lock_guard<std::mutex> lock(peer_mutex_);
    if (peer_.empty()) return Status::fail("no peer has sent a datagram yet, nobody to reply to");
    return Status::ok();
  }

  ssize_t transmit(int fd, const uint8_t* data, size_t size) override {
    std::lock_guard<std::mutex> lock(peer_mutex_);
    return ::sendto(fd, data, size, MSG_NOSIGNAL, peer_.get(), peer_.length);
  }

 private:
  const HostPort local_;
  mutable std::mutex peer_mutex_;  // receive() writes on the I/O thread, senders read
  SocketAddress peer_;
};

}  // namespace

LinkResult make_udp_client_link(const DeviceUrl& url) {
  std::optional<HostPort> bind;
  if (const auto text = url.query_value("bind")) {
    auto parsed = parse_host_port(*text);
    if (!parsed) return LinkResult::fail(url_error(url.text, "bind: " + parsed.error()));
    bind = *parsed;
  }
  return LinkResult(std::make_unique<UdpClientLink>(HostPort{url.host, url.port}, bind));
}

LinkResult make_udp_server_link(const DeviceUrl& url) {
  return LinkResult(std::make_unique<UdpServerLink>(HostPort{url.host, url.port}));
}

}  // namespace k40t::transport
