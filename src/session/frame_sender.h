// Writes frames to the link: one sequence counter per source address (8-bit wrap, section 2.1),
// the checksum coverage the parser locked onto (docs/protocol/decisions.md#a1), and the raw/tx
// handlers in wire order.
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <mutex>
#include <vector>

#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/session/dispatcher.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::session {

class FrameSender {
 public:
  using FrameHandler = std::function<void(const protocol::FrameView&)>;

  // `transport` may be null (every send then fails); `dispatcher` supplies the locked coverage
  // when `coverage` is kAuto. Both must outlive the sender.
  FrameSender(transport::Transport* transport, protocol::CrcCoverage coverage,
              const Dispatcher& dispatcher);

  void on_frame_sent(FrameHandler handler) { sent_handlers_.push_back(std::move(handler)); }

  Status send(protocol::MessageId id, const uint8_t* payload, size_t size, protocol::Address source,
              protocol::Address destination);

  uint64_t frames_sent() const { return frames_sent_.load(std::memory_order_relaxed); }
  uint64_t send_errors() const { return send_errors_.load(std::memory_order_relaxed); }

 private:
  transport::Transport* transport_;
  const protocol::CrcCoverage coverage_;
  const Dispatcher& dispatcher_;
  std::vector<FrameHandler> sent_handlers_;

  std::mutex mutex_;  // sequence numbers and wire order
  struct SenderSequence {
    protocol::Address source;
    uint8_t next = 0;
  };
  std::vector<SenderSequence> sequences_;  // a handful of senders: linear search
  SenderSequence& sequence_of(protocol::Address source);
  std::atomic<uint64_t> frames_sent_{0};
  std::atomic<uint64_t> send_errors_{0};
};

}  // namespace k40t::session
