// Our own commands waiting for their ACKs, matched on (sequence, cmd set, cmd id) as
// docs/psdk.md#frames says the requester must, each with a deadline. No I/O and no threads of its
// own: the session feeds it ACKs and the clock. Thread-safe.
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/psdk/frame.h"

namespace k40t::psdk {

// The outcome of one request. Nothing is thrown: send failures, timeouts and refusals come back
// here with a readable message.
struct AckResult {
  bool sent = false;      // false: the frame could not be built or written
  bool received = false;  // false: no ACK before the deadline (or not sent)
  Data data;              // the ACK's plain DATA, return code first
  std::string message;    // why nothing came back, or the return code's text
  uint16_t sequence = 0;

  uint8_t code() const { return data.size > 0 ? data.bytes[0] : 0xFF; }
  bool ok() const { return received && data.size > 0 && data.bytes[0] == 0x00; }
};

class PendingRequests {
 public:
  using Clock = std::chrono::steady_clock;
  using Callback = std::function<void(const AckResult&)>;

  void add(CommandKey key, uint16_t sequence, Clock::time_point deadline, Callback done);
  // Removes the entry without calling it (the frame could not be sent).
  void cancel(CommandKey key, uint16_t sequence);
  // An ACK arrived: the matching entry's callback, ready to run (outside any lock), or nullopt
  // when nothing waits for it (late, duplicated or foreign).
  std::optional<Callback> take(CommandKey key, uint16_t sequence);
  // Entries whose deadline has passed, removed, with their callbacks.
  struct Expired {
    CommandKey key;
    uint16_t sequence;
    Callback done;
  };
  std::vector<Expired> take_expired(Clock::time_point now);
  // All entries, removed (session stopping).
  std::vector<Expired> take_all();

  std::optional<Clock::time_point> next_deadline() const;
  size_t size() const;

 private:
  struct Entry {
    CommandKey key;
    uint16_t sequence;
    Clock::time_point deadline;
    Callback done;
  };
  mutable std::mutex mutex_;
  std::vector<Entry> entries_;  // few at a time: a linear scan beats a map
};

}  // namespace k40t::psdk
