// What differs between link kinds (serial, pty, UDP, TCP, client or server): how the link is
// established and how bytes move on its file descriptor. FdTransport (fd_transport.h) does the
// rest for all of them: the I/O thread, poll(), reconnection, statistics, the thread-safe write.
//
// Threading: connect(), disconnect(), shutdown(), receive() and preempt_fd() run on the I/O
// thread; can_send(), transmit() and relieve_stalled_write() run on the sending thread with the
// transport's write lock held, which the I/O thread also takes around disconnect() and shutdown().
#pragma once

#include <sys/types.h>

#include <cstddef>
#include <cstdint>
#include <string>

#include "k40t_driver/codec/result.h"
#include "k40t_driver/transport/unique_fd.h"

namespace k40t::transport {

class LinkDriver {
 public:
  virtual ~LinkDriver() = default;

  // Checks that no retry can fix (called by open(), before the I/O thread starts).
  virtual Status preflight() { return Status::ok(); }

  // One attempt to establish the link. Blocking steps go through `waiter` so that close() cuts
  // them short. Returns the fd to poll for input (the driver keeps owning it) or an error naming
  // what was tried ("cannot open /dev/ttyUSB0: No such file or directory (errno 2)").
  virtual Result<int> connect(const Waiter& waiter) = 0;
  // True when the last connect() failed because another program holds the device (its error
  // names the holder): retrying may still succeed once it lets go, but an interactive user wants
  // to hear it at once.
  virtual bool busy() const { return false; }
  // Releases what connect() established; state that outlives one connection (a listening socket)
  // stays until shutdown().
  virtual void disconnect() = 0;
  // Releases everything: the transport is closing.
  virtual void shutdown() { disconnect(); }

  // An extra fd watched while connected; when it becomes readable the link is re-established at
  // once (tcp-server: a new client replaces the current one). -1 for none.
  virtual int preempt_fd() const { return -1; }
  virtual std::string preempt_reason() const { return "link replaced"; }

  // Datagram links: a zero-length read is an empty datagram, not end of file.
  virtual bool is_datagram() const { return false; }
  // read()-like: bytes read, 0 at end of file, -1 with errno set.
  virtual ssize_t receive(int fd, uint8_t* buffer, size_t size);
  // A receive error that does not mean the link is lost (e.g. ICMP port unreachable on UDP).
  virtual bool is_transient_error(int /*error*/) const { return false; }

  // Why a send cannot happen right now although the fd is up (udp-server: no peer yet).
  virtual Status can_send() const { return Status::ok(); }
  // write()-like: bytes written or -1 with errno set. Datagram links send all or nothing.
  virtual ssize_t transmit(int fd, const uint8_t* data, size_t size);
  // Called when a write has made no progress for a while. Returns true if the driver freed room
  // (pty: nobody is reading the slave, so its stale input is dropped).
  virtual bool relieve_stalled_write() { return false; }

  virtual double seconds_per_byte() const { return 0.0; }
};

}  // namespace k40t::transport
