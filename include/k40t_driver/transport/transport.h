// One byte-stream/datagram link to the pod, chosen by URL (see device_url.h):
//   serial:///dev/ttyUSB0?baud=115200   termios raw 8N1, low-latency flag where supported
//   udp://host:port[?bind=addr:port]    datagrams to host:port, optional local bind
//   udp-server://addr:port              binds addr:port, replies to the last peer (simulator)
//   tcp://host:port                     client
//   tcp-server://addr:port              listens, serves one client at a time (simulator)
//   pty:///tmp/k40t_pod                 creates a pseudo-terminal and a symlink to its slave at
//                                       the path (simulator side; the driver opens it as serial)
//
// Servers: a tcp-server is kConnecting/kReconnecting while no client is attached and kConnected
// with one; a udp-server is kConnected once bound, and send() fails until a peer has spoken.
//
// A transport owns one I/O thread. open() returns at once; the thread connects, delivers bytes to
// the receive callback, and on loss (unplugged adapter, TCP reset, pty closed) reports
// kReconnecting and retries with exponential back-off until close(). Callbacks run on the I/O
// thread.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "k40t_driver/codec/result.h"

namespace k40t::transport {

enum class LinkState {
  kClosed,      // not opened, or close() called
  kConnecting,  // first attempt under way
  kConnected,
  kReconnecting,  // lost; waiting for the next attempt (see LinkStats::last_error)
};
const char* to_string(LinkState state);

struct LinkStats {
  uint64_t bytes_sent = 0;
  uint64_t bytes_received = 0;
  uint64_t writes = 0;
  uint64_t reads = 0;
  uint64_t send_errors = 0;
  uint64_t connects = 0;     // successful (re)connections
  uint64_t disconnects = 0;  // losses of an established link
  std::string last_error;    // human-readable, names the device
  // The last attempt found the device held by another program (last_error names it); cleared
  // by a successful connect.
  bool device_busy = false;
};

struct ReconnectPolicy {
  std::chrono::milliseconds initial_delay{100};
  std::chrono::milliseconds max_delay{2000};
  double factor = 2.0;
};

class Transport {
 public:
  using ReceiveCallback = std::function<void(const uint8_t* data, size_t size)>;
  using StateCallback = std::function<void(LinkState state, const std::string& reason)>;

  virtual ~Transport() = default;

  // Set before open().
  void set_receive_callback(ReceiveCallback callback) { on_receive_ = std::move(callback); }
  void set_state_callback(StateCallback callback) { on_state_ = std::move(callback); }
  void set_reconnect_policy(const ReconnectPolicy& policy) { policy_ = policy; }

  // Starts the I/O thread. Fails at once only for errors no retry can fix (e.g. a port number
  // out of range); a device that is absent now is retried in the background.
  virtual Status open() = 0;
  virtual void close() = 0;
  // Writes the whole buffer or fails with a message naming the device (e.g. not connected).
  virtual Status send(const uint8_t* data, size_t size) = 0;

  virtual LinkState state() const = 0;
  virtual LinkStats stats() const = 0;
  virtual std::string url() const = 0;
  // Seconds one byte takes on the wire (10 bits / baud on serial, 0 on networks); used to stamp
  // frames with their start time (docs/protocol/decisions.md#a10).
  virtual double seconds_per_byte() const { return 0.0; }

 protected:
  ReceiveCallback on_receive_;
  StateCallback on_state_;
  ReconnectPolicy policy_;
};

// Creates the transport for `url`; a malformed URL or unknown scheme fails with a message naming
// the URL and what is wrong. Schemes are looked up in a table, not an if/else chain.
Result<std::unique_ptr<Transport>> make_transport(const std::string& url);

// The schemes make_transport() knows, in table order (for help texts and error messages).
std::vector<std::string> known_schemes();

}  // namespace k40t::transport
