// A Transport decorator that misbehaves on demand, for the simulated SKYPORT adapter: it flips
// bits in what it sends, puts garbage between frames, goes silent for a while, and pulls the plug
// (closes the real link and reopens it later). Receiving is passed through untouched. Faults that
// need the protocol (dropped or delayed ACKs, sequence jumps) live in the simulator itself. The
// names follow k40t_sim's FaultSettings.
#pragma once

#include <chrono>
#include <memory>
#include <mutex>
#include <random>

#include "k40t_driver/transport/transport.h"

namespace k40t::psdk::sim {

struct ByteFaults {
  double corrupt_rate = 0.0;  // probability per byte sent of one flipped bit
  double garbage_rate =
      0.0;  // probability per write of 1..garbage_max_bytes random bytes before it
  size_t garbage_max_bytes = 16;
  uint32_t seed = 1;  // the faults are reproducible
};

struct ByteFaultStats {
  uint64_t writes = 0;
  uint64_t bytes_corrupted = 0;
  uint64_t garbage_bursts = 0;
  uint64_t garbage_bytes = 0;
  uint64_t writes_silenced = 0;
  uint64_t disconnects = 0;
};

class FaultyTransport : public transport::Transport {
 public:
  FaultyTransport(std::unique_ptr<transport::Transport> inner, ByteFaults faults);

  Status open() override;
  void close() override;
  Status send(const uint8_t* data, size_t size) override;
  transport::LinkState state() const override { return inner_->state(); }
  transport::LinkStats stats() const override { return inner_->stats(); }
  std::string url() const override { return inner_->url(); }
  double seconds_per_byte() const override { return inner_->seconds_per_byte(); }

  // Switchable while running.
  void set_faults(const ByteFaults& faults);
  ByteFaults faults() const;
  // Writes nothing (and reports success, as a silent device would look) for `duration`.
  void silence_for(std::chrono::milliseconds duration);
  // Closes the real link now; poll() reopens it once `duration` has passed. Not from a receive
  // callback.
  void disconnect_for(std::chrono::milliseconds duration);
  void poll();
  ByteFaultStats fault_stats() const;

 private:
  std::unique_ptr<transport::Transport> inner_;
  mutable std::mutex mutex_;
  ByteFaults faults_;
  std::mt19937 random_;
  std::chrono::steady_clock::time_point silent_until_{};
  bool disconnected_ = false;
  std::chrono::steady_clock::time_point reopen_at_{};
  ByteFaultStats stats_;
};

}  // namespace k40t::psdk::sim
