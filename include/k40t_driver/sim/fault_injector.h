// Misbehaviour on demand for the simulated pod. Every fault is a setting that can change while
// the simulator runs (command line at start, control socket later):
//   corrupt_rate       probability, per byte sent, that one of its bits flips
//   garbage_rate       probability, per frame sent, that 1..garbage_max_bytes random bytes go
//                      out before it (never 0xFD, so the garbage cannot hide a frame's start)
//   drop_ack_rate      probability that a request gets no ACK at all
//   delay_ack_ms       ACKs go out this late (with probability delay_ack_rate)
//   sequence jumps     the sequence numbers of what follows skip N values (one gap of N frames)
//   silence            nothing is sent for N seconds
//   disconnect         the link is closed and reopened after N seconds (FaultyTransport)
// Randomness comes from a seeded generator: a run with the same seed misbehaves the same way.
#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <mutex>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include "k40t_driver/protocol/codec_options.h"

namespace k40t::sim {

using SteadyClock = std::chrono::steady_clock;

struct FaultSettings {
  double corrupt_rate = 0;
  double garbage_rate = 0;
  size_t garbage_max_bytes = 16;
  double drop_ack_rate = 0;
  double delay_ack_ms = 0;
  double delay_ack_rate = 1;
  // Requests with this id (0 = none) are refused with refuse_code and not carried out: the
  // partial-failure cases of multi-request operations (sbus/set) become testable.
  uint32_t refuse_id = 0;
  uint16_t refuse_code = 0x0001;
};

struct FaultCounters {
  uint64_t bytes_corrupted = 0;
  uint64_t garbage_bursts = 0;
  uint64_t garbage_bytes = 0;
  uint64_t acks_dropped = 0;
  uint64_t acks_delayed = 0;
  uint64_t sequence_jumps = 0;     // jumps asked for
  uint64_t frames_renumbered = 0;  // frames sent with shifted numbers since
  uint64_t frames_silenced = 0;    // frames swallowed by a silence
  uint64_t disconnects = 0;
};

class FaultInjector {
 public:
  // `coverage`: how checksums are recomputed after a sequence jump rewrites a frame.
  explicit FaultInjector(uint32_t seed = 1,
                         protocol::CrcCoverage coverage = protocol::CrcCoverage::kHeaderExcluded);

  FaultSettings settings() const;
  void set_settings(const FaultSettings& settings);
  void clear();  // every fault off, silence ended, sequence offset kept (numbers do not go back)

  void jump_sequence(int frames);
  void silence_for(std::chrono::milliseconds duration,
                   SteadyClock::time_point now = SteadyClock::now());
  bool silenced(SteadyClock::time_point now = SteadyClock::now()) const;
  void set_coverage(protocol::CrcCoverage coverage);

  // What goes on the wire for one frame the pod sends: possibly renumbered (checksum recomputed),
  // garbage before it, bits flipped; nothing while silenced.
  std::vector<uint8_t> outgoing(const uint8_t* data, size_t size,
                                SteadyClock::time_point now = SteadyClock::now());

  // Decisions for one ACK.
  bool drop_ack();
  // The code to refuse this request id with, if the refuse fault names it.
  std::optional<uint16_t> refusal(uint32_t request_id) const;
  std::chrono::milliseconds ack_delay();

  void count_disconnect();
  FaultCounters counters() const;
  std::string describe() const;  // one line, for the control socket's "status"

 private:
  bool chance(double probability);  // caller holds the lock
  void renumber(std::vector<uint8_t>& frame) const;

  mutable std::mutex mutex_;
  std::mt19937 rng_;
  protocol::CrcCoverage coverage_;
  FaultSettings settings_;
  FaultCounters counters_;
  uint8_t sequence_offset_ = 0;
  SteadyClock::time_point silent_until_{};
};

}  // namespace k40t::sim
