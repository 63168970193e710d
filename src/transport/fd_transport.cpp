#include "k40t_driver/transport/fd_transport.h"

#include <poll.h>

#include <cerrno>
#include <chrono>
#include <utility>

#include "k40t_driver/transport/backoff.h"
#include "k40t_driver/transport/thread_name.h"

namespace k40t::transport {
namespace {

// Large enough for any UDP datagram, so datagrams are never truncated.
constexpr size_t kReadBufferSize = 65536;
// A write that makes no progress for this long asks the driver to free room (a pty whose slave
// nobody reads). A live reader on a pty drains within microseconds.
constexpr std::chrono::milliseconds kWriteStall{50};
// A write fails when it cannot finish within this time plus twice its own wire time (a 4 KiB
// write at 9600 baud legitimately takes over 4 s).
constexpr std::chrono::milliseconds kWriteTimeout{2000};

}  // namespace

FdTransport::FdTransport(std::string url, std::unique_ptr<LinkDriver> link)
    : url_(std::move(url)), link_(std::move(link)) {}

FdTransport::~FdTransport() {
  close();
}

Status FdTransport::open() {
  std::lock_guard<std::mutex> lifecycle(lifecycle_mutex_);
  if (thread_.joinable()) {
    if (!stop_.raised()) return Status::fail(url_ + ": already open");
    thread_.join();  // stopped from inside a callback; finish that close() now
  }
  if (!stop_.valid()) return Status::fail(url_ + ": cannot create the stop signal (eventfd)");
  if (Status s = check_policy(policy_); !s) return Status::fail(url_ + ": " + s.message());
  if (Status s = link_->preflight(); !s) return Status::fail(url_ + ": " + s.message());
  stop_.clear();
  buffer_.resize(kReadBufferSize);
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    state_ = LinkState::kConnecting;
    reason_.clear();
  }
  thread_ = std::thread(&FdTransport::run, this);
  return Status::ok();
}

void FdTransport::close() {
  if (io_thread_id_.load() == std::this_thread::get_id()) {
    stop_.raise();  // cannot join ourselves; the thread ends when the callback returns
    return;
  }
  std::lock_guard<std::mutex> lifecycle(lifecycle_mutex_);
  if (!thread_.joinable()) return;
  stop_.raise();
  thread_.join();
  io_thread_id_.store(std::thread::id());
}

LinkState FdTransport::state() const {
  std::lock_guard<std::mutex> lock(state_mutex_);
  return state_;
}

LinkStats FdTransport::stats() const {
  std::lock_guard<std::mutex> lock(state_mutex_);
  return stats_;
}

void FdTransport::set_state(LinkState state, const std::string& reason) {
  {
    std::lock_guard<std::mutex> lock(state_mutex_);
    if (state == state_ && reason == reason_) return;
    state_ = state;
    reason_ = reason;
  }
  if (on_state_) on_state_(state, reason);
}

void FdTransport::record_error(const std::string& message, bool send_error) {
  std::lock_guard<std::mutex> lock(state_mutex_);
  stats_.last_error = message;
  if (send_error) ++stats_.send_errors;
}

void FdTransport::attach(int fd) {
  {
    std::lock_guard<std::mutex> lock(write_mutex_);
    fd_ = fd;
  }
  std::lock_guard<std::mutex> lock(state_mutex_);
  ++stats_.connects;
  stats_.device_busy = false;
}

void FdTransport::detach() {
  std::lock_guard<std::mutex> lock(write_mutex_);
  link_->disconnect();
  fd_ = -1;
}

void FdTransport::run() {
  name_this_thread("k40t_io");
  io_thread_id_.store(std::this_thread::get_id());
  const Waiter waiter(stop_);
  Backoff backoff(policy_);
  set_state(LinkState::kConnecting, "connecting to " + url_);
  while (!waiter.stopped()) {
    const Result<int> fd = link_->connect(waiter);
    if (!fd) {
      if (waiter.stopped()) break;
      const std::string error = url_ + ": " + fd.error();
      record_error(error, false);
      {
        std::lock_guard<std::mutex> lock(state_mutex_);
        stats_.device_busy = link_->busy();
      }
      set_state(LinkState::kReconnecting, error);
      if (!waiter.sleep(backoff.next())) break;
      continue;
    }
    attach(*fd);
    backoff.reset();
    set_state(LinkState::kConnected, "connected to " + url_);
    const Loss loss = pump(*fd);
    detach();
    if (loss.reason.empty()) break;  // close()
    {
      std::lock_guard<std::mutex> lock(state_mutex_);
      ++stats_.disconnects;
      stats_.last_error = loss.reason;
    }
    set_state(LinkState::kReconnecting, loss.reason);
    if (!loss.preempted && !waiter.sleep(backoff.next())) break;
  }
  {
    std::lock_guard<std::mutex> lock(write_mutex_);
    link_->shutdown();
    fd_ = -1;
  }
  set_state(LinkState::kClosed, "closed");
  io_thread_id_.store(std::thread::id());  // ids get reused; no later thread may pass for this one
}

FdTransport::Loss FdTransport::pump(int fd) {
  while (true) {
    const int preempt = link_->preempt_fd();
    pollfd entries[3] = {{stop_.fd(), POLLIN, 0}, {fd, POLLIN, 0}, {preempt, POLLIN, 0}};
    const nfds_t count = preempt >= 0 ? 3 : 2;
    if (::poll(entries, count, -1) < 0) {
      if (errno == EINTR) continue;
      return {url_ + ": poll failed: " + errno_text(errno)};
    }
    if (entries[0].revents != 0) return {};
    if (entries[1].revents != 0) {
      Loss loss = read_once(fd, entries[1].revents);
      if (!loss.reason.empty()) return loss;
    }
    if (count == 3 && entries[2].revents != 0) {
      return {url_ + ": " + link_->preempt_reason(), true};
    }
  }
}

FdTransport::Loss FdTransport::read_once(int fd, short revents) {
  if ((revents & POLLNVAL) != 0) return {url_ + ": the device's file descriptor became invalid"};
  const ssize_t n = link_->receive(fd, buffer_.data(), buffer_.size());
  if (n > 0 || (n == 0 && link_->is_datagram())) {
    {
      std::lock_guard<std::mutex> lock(state_mutex_);
      ++stats_.reads;
      stats_.bytes_received += static_cast<uint64_t>(n);
    }
    if (n > 0 && on_receive_) on_receive_(buffer_.data(), static_cast<size_t>(n));
    return {};
  }
  if (n == 0) return {url_ + ": end of file (the other side closed the link)"};
  const int error = errno;
  if (error == EAGAIN || error == EWOULDBLOCK || error == EINTR) {
    // Nothing to read although poll() woke us: only a hang-up or error condition explains that.
    if ((revents & (POLLHUP | POLLERR)) != 0) return {url_ + ": hang-up (device gone)"};
    return {};
  }
  if (link_->is_transient_error(error)) {
    record_error(url_ + ": receive error, link kept: " + errno_text(error), false);
    return {};
  }
  return {url_ + ": read failed: " + errno_text(error)};
}

Status FdTransport::send(const uint8_t* data, size_t size) {
  Status status = write_all(data, size);
  if (status) {
    std::lock_guard<std::mutex> lock(state_mutex_);
    ++stats_.writes;
    stats_.bytes_sent += size;
  }
  return status;
}

Status FdTransport::write_all(const uint8_t* data, size_t size) {
  std::lock_guard<std::mutex> write_lock(write_mutex_);
  if (fd_ < 0) {
    const LinkState now = state();
    {
      std::lock_guard<std::mutex> lock(state_mutex_);
      ++stats_.send_errors;
    }
    return Status::fail(url_ + ": not connected (" + to_string(now) + ")");
  }
  if (Status s = link_->can_send(); !s) {
    record_error(url_ + ": " + s.message(), true);
    return Status::fail(url_ + ": " + s.message());
  }
  const Waiter waiter(stop_);
  const auto wire_time = std::chrono::duration_cast<std::chrono::milliseconds>(
      std::chrono::duration<double>(2.0 * static_cast<double>(size) * link_->seconds_per_byte()));
  const auto timeout = kWriteTimeout + wire_time;
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  size_t done = 0;
  std::string failure;
  while (done < size && failure.empty()) {
    const ssize_t n = link_->transmit(fd_, data + done, size - done);
    if (n > 0) {
      done += static_cast<size_t>(n);
      continue;
    }
    const int error = n < 0 ? errno : EAGAIN;
    if (error == EINTR) continue;
    if (error != EAGAIN && error != EWOULDBLOCK) {
      failure = "write failed: " + errno_text(error);
      break;
    }
    switch (waiter.wait(fd_, POLLOUT, kWriteStall)) {
      case Waiter::Outcome::kReady:
        break;
      case Waiter::Outcome::kStopped:
        failure = "closing";
        break;
      case Waiter::Outcome::kTimeout:
        if (std::chrono::steady_clock::now() >= deadline) {
          failure = "write timed out after " + std::to_string(timeout.count()) + " ms";
        } else {
          link_->relieve_stalled_write();
        }
        break;
    }
  }
  if (failure.empty()) return Status::ok();
  const std::string message = url_ + ": " + failure + " (" + std::to_string(done) + " of " +
                              std::to_string(size) + " bytes written)";
  record_error(message, true);
  return Status::fail(message);
}

}  // namespace k40t::transport
