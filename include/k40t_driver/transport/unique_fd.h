// Small POSIX helpers shared by the transports: an owning file descriptor, errno text, and the
// cancellable wait every blocking step of a transport goes through so close() is prompt.
#pragma once

#include <chrono>
#include <string>

#include "k40t_driver/codec/result.h"

namespace k40t::transport {

// Owns one file descriptor; closes it on destruction or reset().
class UniqueFd {
 public:
  UniqueFd() = default;
  explicit UniqueFd(int fd) : fd_(fd) {}
  UniqueFd(UniqueFd&& other) noexcept : fd_(other.release()) {}
  UniqueFd& operator=(UniqueFd&& other) noexcept {
    if (this != &other) reset(other.release());
    return *this;
  }
  UniqueFd(const UniqueFd&) = delete;
  UniqueFd& operator=(const UniqueFd&) = delete;
  ~UniqueFd() { reset(); }

  int get() const { return fd_; }
  bool valid() const { return fd_ >= 0; }
  int release() {
    int fd = fd_;
    fd_ = -1;
    return fd;
  }
  void reset(int fd = -1);

 private:
  int fd_ = -1;
};

// "No such file or directory (errno 2)" for the given errno value.
std::string errno_text(int error);

// Sets O_NONBLOCK (and FD_CLOEXEC) on fd; fails with errno text.
Status make_nonblocking(int fd);

// A level-triggered stop flag that poll() can watch (an eventfd): once raised, every wait that
// includes it returns at once until clear() is called.
class StopSignal {
 public:
  StopSignal();
  bool valid() const { return fd_.valid(); }
  int fd() const { return fd_.get(); }
  void raise();
  void clear();
  bool raised() const;

 private:
  UniqueFd fd_;
};

// Waits on one fd or a timeout, but gives up as soon as the stop signal is raised. Transports use
// it for every blocking step (connect, accept, back-off sleep, a full write buffer).
class Waiter {
 public:
  enum class Outcome { kReady, kTimeout, kStopped };
  explicit Waiter(const StopSignal& stop) : stop_(stop) {}

  // A negative timeout waits forever. kReady also covers POLLERR/POLLHUP on fd; the caller's next
  // read or write reports the actual error.
  Outcome wait(int fd, short events, std::chrono::milliseconds timeout) const;
  // false when stopped before the delay ran out.
  bool sleep(std::chrono::milliseconds delay) const;
  bool stopped() const { return stop_.raised(); }

 private:
  const StopSignal& stop_;
};

}  // namespace k40t::transport
