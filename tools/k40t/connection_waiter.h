// Waits until a session's transport reports a connection (serial and network links connect in the
// background after open()) or until it finds the device held by another program, remembering the
// last reason the link gave. Shared by send and probe.
#pragma once

#include <chrono>
#include <condition_variable>
#include <mutex>
#include <string>

#include "k40t_driver/session/session.h"

namespace k40t::tool {

class ConnectionWaiter {
 public:
  void update(transport::LinkState state, const std::string& reason) {
    std::lock_guard<std::mutex> lock(mutex_);
    connected_ = state == transport::LinkState::kConnected;
    if (!reason.empty()) last_reason_ = reason;
    changed_.notify_all();
  }
  bool wait(std::chrono::milliseconds deadline, const session::Session& session) {
    std::unique_lock<std::mutex> lock(mutex_);
    const bool woken = changed_.wait_for(lock, deadline, [&] {
      return connected_ || session.link_state() == transport::LinkState::kConnected ||
             session.stats().link.device_busy;
    });
    return woken && !session.stats().link.device_busy;
  }
  std::string last_reason() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return last_reason_;
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  bool connected_ = false;
  std::string last_reason_;
};

}  // namespace k40t::tool
