// Helpers for the transport tests: collect what a transport receives and which states it reports,
// wait for conditions with generous deadlines (never assert on elapsed time), pick free loopback
// ports and make scratch directories.
#pragma once

#include <arpa/inet.h>
#include <netinet/in.h>
#include <stdlib.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <mutex>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "eventually.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::transport::testing {

using k40t::test::eventually;

// Accumulates received bytes.
class ByteSink {
 public:
  Transport::ReceiveCallback callback() {
    return [this](const uint8_t* data, size_t size) {
      std::lock_guard<std::mutex> lock(mutex_);
      bytes_.insert(bytes_.end(), data, data + size);
      ++callbacks_;
    };
  }
  size_t size() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return bytes_.size();
  }
  size_t callbacks() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return callbacks_;
  }
  std::vector<uint8_t> bytes() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return bytes_;
  }
  bool wait_for_size(size_t size) {
    return eventually([&] { return this->size() >= size; });
  }
  void clear() {
    std::lock_guard<std::mutex> lock(mutex_);
    bytes_.clear();
    callbacks_ = 0;
  }

 private:
  mutable std::mutex mutex_;
  std::vector<uint8_t> bytes_;
  size_t callbacks_ = 0;
};

// Records every state the transport reports, with its reason.
class StateLog {
 public:
  Transport::StateCallback callback() {
    return [this](LinkState state, const std::string& reason) {
      std::lock_guard<std::mutex> lock(mutex_);
      states_.push_back(state);
      reasons_.push_back(reason);
    };
  }
  size_t count(LinkState state) const {
    std::lock_guard<std::mutex> lock(mutex_);
    return static_cast<size_t>(std::count(states_.begin(), states_.end(), state));
  }
  // Waits until `state` has been reported at least `times` times in all.
  bool wait_for(LinkState state, size_t times = 1) {
    return eventually([&] { return count(state) >= times; });
  }
  std::vector<LinkState> states() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return states_;
  }
  std::string last_reason(LinkState state) const {
    std::lock_guard<std::mutex> lock(mutex_);
    for (size_t i = states_.size(); i-- > 0;) {
      if (states_[i] == state) return reasons_[i];
    }
    return {};
  }

 private:
  mutable std::mutex mutex_;
  std::vector<LinkState> states_;
  std::vector<std::string> reasons_;
};

// A transport from `url` wired to a sink and a state log, with a quick reconnect policy.
struct Endpoint {
  ByteSink received;
  StateLog log;
  std::unique_ptr<Transport>
      transport;  // last: destroyed (and joined) before its callbacks' targets

  explicit Endpoint(const std::string& url);
  Status send(const std::vector<uint8_t>& bytes) {
    return transport->send(bytes.data(), bytes.size());
  }
};

inline Endpoint::Endpoint(const std::string& url) {
  auto made = make_transport(url);
  if (!made) throw std::runtime_error(made.error());
  transport = std::move(made).value();
  transport->set_receive_callback(received.callback());
  transport->set_state_callback(log.callback());
  ReconnectPolicy quick;
  quick.initial_delay = std::chrono::milliseconds(10);
  quick.max_delay = std::chrono::milliseconds(100);
  transport->set_reconnect_policy(quick);
}

// A plain socket bound to 127.0.0.1 on a port the kernel picks (bind port 0, read it back).
class LoopbackSocket {
 public:
  explicit LoopbackSocket(int socket_type) : fd_(::socket(AF_INET, socket_type, 0)) {
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t length = sizeof address;
    if (::bind(fd_, reinterpret_cast<sockaddr*>(&address), sizeof address) == 0 &&
        ::getsockname(fd_, reinterpret_cast<sockaddr*>(&address), &length) == 0) {
      port_ = ntohs(address.sin_port);
    }
  }
  ~LoopbackSocket() { close(); }
  LoopbackSocket(const LoopbackSocket&) = delete;
  LoopbackSocket& operator=(const LoopbackSocket&) = delete;

  int fd() const { return fd_; }
  uint16_t port() const { return port_; }  // 0 if binding failed (URLs then reject it)
  void close() {
    if (fd_ >= 0) ::close(fd_);
    fd_ = -1;
  }

 private:
  int fd_;
  uint16_t port_ = 0;
};

// A port on 127.0.0.1 that was free a moment ago.
inline uint16_t free_loopback_port(int socket_type) {
  return LoopbackSocket(socket_type).port();
}

// A fresh directory under the system's temp dir, removed with its contents on destruction.
class ScratchDir {
 public:
  ScratchDir() {
    std::string pattern = (std::filesystem::temp_directory_path() / "k40t_transport_XXXXXX");
    if (::mkdtemp(pattern.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
    path_ = pattern;
  }
  ~ScratchDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

inline std::vector<uint8_t> random_bytes(size_t size, uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<uint8_t> bytes(size);
  for (auto& b : bytes) b = static_cast<uint8_t>(rng());
  return bytes;
}

}  // namespace k40t::transport::testing
