#include "k40t_driver/transport/unique_fd.h"

#include <fcntl.h>
#include <poll.h>
#include <sys/eventfd.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <cstring>

namespace k40t::transport {

void UniqueFd::reset(int fd) {
  if (fd_ >= 0) ::close(fd_);
  fd_ = fd;
}

std::string errno_text(int error) {
  return std::string(std::strerror(error)) + " (errno " + std::to_string(error) + ")";
}

Status make_nonblocking(int fd) {
  const int flags = ::fcntl(fd, F_GETFL);
  if (flags < 0 || ::fcntl(fd, F_SETFL, flags | O_NONBLOCK) < 0 ||
      ::fcntl(fd, F_SETFD, FD_CLOEXEC) < 0) {
    return Status::fail("cannot make fd non-blocking: " + errno_text(errno));
  }
  return Status::ok();
}

StopSignal::StopSignal() : fd_(::eventfd(0, EFD_NONBLOCK | EFD_CLOEXEC)) {}

void StopSignal::raise() {
  const uint64_t one = 1;
  // A full counter (impossible in practice) still leaves the fd readable, which is all we need.
  [[maybe_unused]] ssize_t written = ::write(fd_.get(), &one, sizeof one);
}

void StopSignal::clear() {
  uint64_t count = 0;
  [[maybe_unused]] ssize_t read_bytes = ::read(fd_.get(), &count, sizeof count);
}

bool StopSignal::raised() const {
  pollfd entry{fd_.get(), POLLIN, 0};
  return ::poll(&entry, 1, 0) > 0 && (entry.revents & POLLIN) != 0;
}

namespace {

// Milliseconds left until `deadline`, rounded up, for poll(); -1 for "forever".
int poll_timeout(std::chrono::steady_clock::time_point deadline, bool forever) {
  if (forever) return -1;
  const auto left = deadline - std::chrono::steady_clock::now();
  if (left <= std::chrono::steady_clock::duration::zero()) return 0;
  return static_cast<int>(std::chrono::ceil<std::chrono::milliseconds>(left).count());
}

}  // namespace

Waiter::Outcome Waiter::wait(int fd, short events, std::chrono::milliseconds timeout) const {
  const bool forever = timeout.count() < 0;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (true) {
    pollfd entries[2] = {{stop_.fd(), POLLIN, 0}, {fd, events, 0}};
    const int count = ::poll(entries, fd >= 0 ? 2 : 1, poll_timeout(deadline, forever));
    if (count < 0 && errno == EINTR) continue;
    if (entries[0].revents != 0) return Outcome::kStopped;
    // Ready includes POLLERR/POLLHUP and a failed poll(): the caller's next read or write on the
    // fd reports the actual error.
    if (count != 0) return Outcome::kReady;
    if (poll_timeout(deadline, forever) == 0) return Outcome::kTimeout;
  }
}

bool Waiter::sleep(std::chrono::milliseconds delay) const {
  return wait(-1, 0, delay) != Outcome::kStopped;
}

}  // namespace k40t::transport
