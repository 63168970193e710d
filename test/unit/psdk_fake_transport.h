// An in-memory Transport for session tests: bytes sent are recorded and, when two links are
// paired, delivered to the peer; bytes are delivered to the receive callback on the link's own
// I/O thread, as a real transport does.
#pragma once

#include <chrono>
#include <condition_variable>
#include <deque>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

#include "k40t_driver/transport/transport.h"

namespace k40t::psdk::testing {

class FakeLink : public transport::Transport {
 public:
  ~FakeLink() override { close(); }

  static void pair(FakeLink& a, FakeLink& b) {
    a.peer_ = &b;
    b.peer_ = &a;
  }

  Status open() override {
    std::lock_guard<std::mutex> lock(mutex_);
    if (open_) return Status::ok();
    open_ = true;
    stop_ = false;
    thread_ = std::thread([this] { run(); });
    return Status::ok();
  }
  void close() override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!open_) return;
      open_ = false;
      stop_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  Status send(const uint8_t* data, size_t size) override {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!open_) return Status::fail("fake link: not open");
      if (fail_sends_) return Status::fail("fake link: send refused");
      sent_.emplace_back(data, data + size);
    }
    sent_wake_.notify_all();
    if (peer_ != nullptr) peer_->inject(data, size);
    return Status::ok();
  }
  transport::LinkState state() const override {
    std::lock_guard<std::mutex> lock(mutex_);
    return open_ ? transport::LinkState::kConnected : transport::LinkState::kClosed;
  }
  transport::LinkStats stats() const override { return {}; }
  std::string url() const override { return "fake://"; }

  // Bytes "from the wire", delivered on this link's I/O thread.
  void inject(const uint8_t* data, size_t size) {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      incoming_.emplace_back(data, data + size);
    }
    wake_.notify_all();
  }
  void inject(const std::vector<uint8_t>& bytes) { inject(bytes.data(), bytes.size()); }

  void refuse_sends(bool refuse) {
    std::lock_guard<std::mutex> lock(mutex_);
    fail_sends_ = refuse;
  }

  // Waits (generously) until at least `n` sends happened; returns a copy of all of them.
  std::vector<std::vector<uint8_t>> wait_for_sent(
      size_t n, std::chrono::seconds deadline = std::chrono::seconds(10)) {
    std::unique_lock<std::mutex> lock(mutex_);
    sent_wake_.wait_for(lock, deadline, [&] { return sent_.size() >= n; });
    return sent_;
  }
  std::vector<std::vector<uint8_t>> sent() const {
    std::lock_guard<std::mutex> lock(mutex_);
    return sent_;
  }
  // Waits until everything injected so far has been handed to the receive callback.
  void drain() {
    std::unique_lock<std::mutex> lock(mutex_);
    idle_.wait_for(lock, std::chrono::seconds(10),
                   [&] { return incoming_.empty() && !delivering_; });
  }

 private:
  void run() {
    std::unique_lock<std::mutex> lock(mutex_);
    while (true) {
      wake_.wait(lock, [&] { return stop_ || !incoming_.empty(); });
      if (stop_) return;
      std::vector<uint8_t> chunk = std::move(incoming_.front());
      incoming_.pop_front();
      delivering_ = true;
      lock.unlock();
      if (on_receive_) on_receive_(chunk.data(), chunk.size());
      lock.lock();
      delivering_ = false;
      idle_.notify_all();
    }
  }

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::condition_variable sent_wake_;
  std::condition_variable idle_;
  std::thread thread_;
  bool open_ = false;
  bool stop_ = false;
  bool fail_sends_ = false;
  bool delivering_ = false;
  std::deque<std::vector<uint8_t>> incoming_;
  std::vector<std::vector<uint8_t>> sent_;
  FakeLink* peer_ = nullptr;
};

}  // namespace k40t::psdk::testing
