// The simulator's link: a Transport that wraps the real one (pty, UDP or TCP server) and puts the
// FaultInjector and the CaptureWriter on the path of every byte. It can also pull the plug:
// disconnect_for(N) closes the real link (the host sees the pty hang up or the TCP connection
// drop) and poll() opens a fresh one once N has passed, from the same URL — a new pty behind the
// same symlink, a listening socket on the same port.
#pragma once

#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <string>

#include "k40t_driver/sim/capture_writer.h"
#include "k40t_driver/sim/fault_injector.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::sim {

class FaultyTransport : public transport::Transport {
 public:
  using Factory = std::function<Result<std::unique_ptr<transport::Transport>>()>;

  // `capture` may be null. Both outlive this object.
  FaultyTransport(Factory factory, std::string url, FaultInjector& faults, CaptureWriter* capture);
  ~FaultyTransport() override;

  Status open() override;
  void close() override;
  Status send(const uint8_t* data, size_t size) override;
  transport::LinkState state() const override;
  transport::LinkStats stats() const override;
  std::string url() const override { return url_; }
  double seconds_per_byte() const override;

  void disconnect_for(std::chrono::milliseconds duration,
                      SteadyClock::time_point now = SteadyClock::now());
  // Reopens the link when a disconnect has run its time; call it regularly.
  void poll(SteadyClock::time_point now = SteadyClock::now());
  bool disconnected() const;

 private:
  Status open_inner();
  void report(transport::LinkState state, const std::string& reason);

  Factory factory_;
  std::string url_;
  FaultInjector& faults_;
  CaptureWriter* capture_;
  mutable std::mutex mutex_;
  std::unique_ptr<transport::Transport> inner_;
  transport::LinkStats retired_;  // what closed links carried, so stats() keep counting
  bool opened_ = false;
  bool disconnected_ = false;
  SteadyClock::time_point reopen_at_{};
};

}  // namespace k40t::sim
