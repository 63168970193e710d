// Two sessions joined by FakeTransport: the driver's (host role) and a pod's (the simulator's
// role: own address 0x04/0x01, answering requests through handlers). Handlers are registered by
// the test before start(). Waiting uses generous deadlines only.
#pragma once

#include <gtest/gtest.h>

#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <vector>

#include "fake_transport.h"
#include "k40t_driver/session/session.h"

namespace k40t::test {

inline session::SessionOptions host_options(std::chrono::milliseconds timeout, int retries) {
  session::SessionOptions o;
  o.ack_timeout = timeout;
  o.retries = retries;
  return o;
}

inline session::SessionOptions pod_options() {
  session::SessionOptions o;
  o.own_address = protocol::kCameraAddress;
  o.ack_timeout = std::chrono::milliseconds(2000);
  o.retries = 0;
  return o;
}

struct SessionLink {
  explicit SessionLink(
      session::SessionOptions host_opts = host_options(std::chrono::milliseconds(2000), 0),
      session::SessionOptions pod_opts = pod_options()) {
    auto ends = FakeTransport::pair();
    host_wire = ends.first.get();
    pod_wire = ends.second.get();
    host = std::make_unique<session::Session>(std::move(ends.first), host_opts);
    pod = std::make_unique<session::Session>(std::move(ends.second), pod_opts);
  }
  void start() {
    ASSERT_TRUE(pod->start());
    ASSERT_TRUE(host->start());
  }

  FakeTransport* host_wire = nullptr;
  FakeTransport* pod_wire = nullptr;
  std::unique_ptr<session::Session> host;
  std::unique_ptr<session::Session> pod;
};

// Collects values from handler threads; the test waits for a count with a generous deadline.
template <class T>
class Collector {
 public:
  void add(T value) {
    std::lock_guard<std::mutex> lock(mutex_);
    items_.push_back(std::move(value));
    changed_.notify_all();
  }
  bool wait_for_count(size_t n,
                      std::chrono::milliseconds deadline = std::chrono::milliseconds(10000)) {
    std::unique_lock<std::mutex> lock(mutex_);
    return changed_.wait_for(lock, deadline, [&] { return items_.size() >= n; });
  }
  std::vector<T> items() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return items_;
  }
  size_t size() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return items_.size();
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::vector<T> items_;
};

// The bytes of one ACK payload: response code big-endian (docs/protocol/decisions.md#a2), then
// `extra`.
inline protocol::Payload ack_payload(uint16_t code, std::vector<uint8_t> extra = {}) {
  protocol::Payload p;
  p.bytes[0] = static_cast<uint8_t>(code >> 8);
  p.bytes[1] = static_cast<uint8_t>(code);
  for (size_t i = 0; i < extra.size(); ++i) p.bytes[2 + i] = extra[i];
  p.size = 2 + extra.size();
  return p;
}

}  // namespace k40t::test
