// One operation shared between the thread that runs a goal and the threads that feed it (the
// link's I/O thread with status frames, the session's request thread with the ACK): every access
// under one mutex, and a wait for "something changed" so the goal thread sleeps between frames
// yet wakes at once for a status, a cancel or shutdown. ROS-free.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <utility>

namespace k40t::operations {

template <class Op>
class SharedOperation {
 public:
  explicit SharedOperation(Op op) : op_(std::move(op)) {}

  // Runs f(op) under the lock and wakes the waiter; returns what f returns.
  template <class F>
  auto update(F&& f) {
    std::lock_guard<std::mutex> lock(mutex_);
    ++changes_;
    changed_.notify_all();
    return f(op_);
  }
  // Runs f(op) under the lock without waking the waiter (the waiter's own checks).
  template <class F>
  auto inspect(F&& f) {
    std::lock_guard<std::mutex> lock(mutex_);
    return f(op_);
  }
  template <class F>
  auto read(F&& f) const {
    std::lock_guard<std::mutex> lock(mutex_);
    return f(static_cast<const Op&>(op_));
  }
  // Waits until an update() after the call that returned `seen`, or `timeout`; returns the count
  // of updates so far (pass it back as `seen`).
  uint64_t wait_for_change(uint64_t seen, std::chrono::milliseconds timeout) {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait_for(lock, timeout, [&] { return changes_ != seen; });
    return changes_;
  }

 private:
  mutable std::mutex mutex_;
  std::condition_variable changed_;
  uint64_t changes_ = 0;
  Op op_;
};

}  // namespace k40t::operations
