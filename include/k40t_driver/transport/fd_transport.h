// The one Transport implementation: a LinkDriver (link_driver.h) plus the machinery every link
// shares. Its I/O thread connects, polls the fd and a stop signal, hands received bytes to the
// receive callback, and on loss reports kReconnecting and retries with exponential back-off until
// close(). send() may be called from any thread.
#pragma once

#include <atomic>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "k40t_driver/transport/link_driver.h"
#include "k40t_driver/transport/transport.h"
#include "k40t_driver/transport/unique_fd.h"

namespace k40t::transport {

class FdTransport final : public Transport {
 public:
  FdTransport(std::string url, std::unique_ptr<LinkDriver> link);
  // Closes. Must not run inside one of the transport's own callbacks (it would join itself).
  ~FdTransport() override;

  Status open() override;
  // Prompt (the I/O thread is woken through the stop signal) and idempotent. Called from a
  // callback (i.e. on the I/O thread) it only asks the thread to stop; a later close() or the
  // destructor joins it.
  void close() override;
  Status send(const uint8_t* data, size_t size) override;

  LinkState state() const override;
  LinkStats stats() const override;
  std::string url() const override { return url_; }
  double seconds_per_byte() const override { return link_->seconds_per_byte(); }

 private:
  struct Loss {
    std::string reason;  // empty: stopped by close()
    bool preempted = false;
  };

  void run();
  Loss pump(int fd);
  Loss read_once(int fd, short revents);
  void attach(int fd);
  void detach();
  void set_state(LinkState state, const std::string& reason);
  void record_error(const std::string& message, bool send_error);
  Status write_all(const uint8_t* data, size_t size);

  const std::string url_;
  const std::unique_ptr<LinkDriver> link_;
  StopSignal stop_;
  std::vector<uint8_t> buffer_;  // I/O thread only

  std::mutex lifecycle_mutex_;  // open()/close()
  std::thread thread_;
  std::atomic<std::thread::id> io_thread_id_{};

  std::mutex write_mutex_;  // guards fd_ and the driver's send side
  int fd_ = -1;             // the connected fd, -1 when not connected

  mutable std::mutex state_mutex_;
  LinkState state_ = LinkState::kClosed;
  std::string reason_;  // of the last reported state, to report changes only
  LinkStats stats_;
};

}  // namespace k40t::transport
