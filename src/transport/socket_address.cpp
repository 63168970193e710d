#include "socket_address.h"

#include <netdb.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <cerrno>
#include <cstring>

namespace k40t::transport {

std::string SocketAddress::text() const {
  char host[NI_MAXHOST] = {};
  char port[NI_MAXSERV] = {};
  if (length == 0 || ::getnameinfo(get(), length, host, sizeof host, port, sizeof port,
                                   NI_NUMERICHOST | NI_NUMERICSERV) != 0) {
    return "(unknown address)";
  }
  return family() == AF_INET6 ? "[" + std::string(host) + "]:" + port
                              : std::string(host) + ":" + port;
}

Result<SocketAddress> resolve_address(const std::string& host, uint16_t port, int socket_type,
                                      bool passive) {
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = socket_type;
  hints.ai_flags = AI_NUMERICSERV | (passive ? AI_PASSIVE : 0);
  addrinfo* found = nullptr;
  const std::string service = std::to_string(port);
  const int rc = ::getaddrinfo(host.c_str(), service.c_str(), &hints, &found);
  if (rc != 0 || found == nullptr) {
    return Result<SocketAddress>::fail("cannot resolve '" + host + "': " +
                                       (rc == EAI_SYSTEM ? errno_text(errno) : gai_strerror(rc)));
  }
  SocketAddress address;
  std::memcpy(&address.storage, found->ai_addr, found->ai_addrlen);
  address.length = found->ai_addrlen;
  ::freeaddrinfo(found);
  return address;
}

Result<UniqueFd> open_socket(const SocketAddress& address, int socket_type) {
  UniqueFd fd(::socket(address.family(), socket_type | SOCK_NONBLOCK | SOCK_CLOEXEC, 0));
  if (!fd.valid()) return Result<UniqueFd>::fail("cannot create a socket: " + errno_text(errno));
  return fd;
}

Status bind_socket(int fd, const SocketAddress& address, bool reuse_address) {
  const int on = 1;
  if (reuse_address) ::setsockopt(fd, SOL_SOCKET, SO_REUSEADDR, &on, sizeof on);
  if (::bind(fd, address.get(), address.length) < 0) {
    return Status::fail("cannot bind to " + address.text() + ": " + errno_text(errno));
  }
  return Status::ok();
}

}  // namespace k40t::transport
