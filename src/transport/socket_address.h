// Socket addresses for the UDP and TCP links: name resolution, printing, socket creation.
#pragma once

#include <sys/socket.h>

#include <cstdint>
#include <string>

#include "k40t_driver/codec/result.h"
#include "k40t_driver/transport/unique_fd.h"

namespace k40t::transport {

struct SocketAddress {
  sockaddr_storage storage{};
  socklen_t length = 0;

  int family() const { return storage.ss_family; }
  const sockaddr* get() const { return reinterpret_cast<const sockaddr*>(&storage); }
  bool empty() const { return length == 0; }
  std::string text() const;  // "127.0.0.1:5555" or "[::1]:5555"
};

// First address getaddrinfo() gives for host:port; `passive` for addresses to bind to.
Result<SocketAddress> resolve_address(const std::string& host, uint16_t port, int socket_type,
                                      bool passive);

// A non-blocking, close-on-exec socket of the address's family.
Result<UniqueFd> open_socket(const SocketAddress& address, int socket_type);

// Binds `fd` to `address`. `reuse_address` sets SO_REUSEADDR first, so a restarted TCP server
// gets its port back while the old connection is in TIME_WAIT (not for UDP, where it would let two
// sockets share the port).
Status bind_socket(int fd, const SocketAddress& address, bool reuse_address);

}  // namespace k40t::transport
