// Frames in, typed messages out, with no I/O: the parser plus routing by message id. The Session
// owns one for its link; replay mode (frames from a bag) and the tools use one directly.
//
// Threading: feed()/feed_frame()/reset() may be called from one thread at a time (a mutex
// serialises them); handlers run on that thread, inside feed(), and must not feed or reset the
// same dispatcher. Register every handler before the first feed. stats() is safe from any thread.
//
// Steady-state receive path: parsing and routing allocate nothing; a typed handler's decode
// allocates only if its message has a text field longer than the small-string buffer.
#pragma once

#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <unordered_map>
#include <vector>

#include "k40t_driver/protocol/ack_order_setting.h"
#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/parser.h"

namespace k40t::session {

// A consistent copy of the dispatcher's counters, taken under its lock.
struct DispatcherStats {
  protocol::ParserStats parser;
  uint64_t decode_errors = 0;
  protocol::CrcCoverage locked_coverage = protocol::CrcCoverage::kAuto;
};

class Dispatcher {
 public:
  using FrameHandler = std::function<void(const protocol::FrameView&)>;
  using DecodeErrorHandler = std::function<void(const protocol::FrameView&, const std::string&)>;

  // `ack_order`: the link's shared ACK byte order (the Session's); a new one from `codec` if null.
  // Every ACK updates it (ack_byte_order: auto) before any handler sees the ACK.
  Dispatcher(protocol::CrcCoverage coverage, const protocol::CodecOptions& codec,
             std::shared_ptr<protocol::AckOrderSetting> ack_order = nullptr);

  // Register before feeding. Msg::kId selects the frames; a frame whose payload does not decode
  // goes to the decode-error handler instead (and is counted). Several handlers may share an id.
  template <class Msg>
  void on(std::function<void(const Msg&, const protocol::FrameView&)> handler);
  // Every good frame, before typed routing (raw/rx topics, monitors).
  void on_frame(FrameHandler handler);
  // Every good frame, after the frame handlers and the typed routes. The session completes its
  // requests here: whoever waits on a request then finds every observer (box tracking, capture
  // mode, conventions, published state) already updated by the ACK that ends it.
  void on_frame_routed(FrameHandler handler);
  void on_decode_error(DecodeErrorHandler handler);

  // Bytes as they arrive from a link, in any chunking.
  void feed(const uint8_t* data, size_t size);
  // One whole frame, e.g. from a bag; it goes through the parser too, so counters stay honest.
  void feed_frame(const uint8_t* frame, size_t size) { feed(frame, size); }

  // The parser's live counters: read them from a handler or while nobody feeds (replay, tools);
  // from other threads use stats().
  const protocol::ParserStats& parser_stats() const;
  // The same rule: bytes that start a frame still arriving (a capture cut short ends with them).
  size_t buffered_bytes() const;
  uint64_t decode_errors() const;
  protocol::CrcCoverage locked_coverage() const;
  DispatcherStats stats() const;
  // The options the typed decoders use now: ack_byte_order as the link's setting has it.
  protocol::CodecOptions codec() const { return ack_order_->codec_with(codec_); }
  const protocol::AckOrderSetting& ack_order() const { return *ack_order_; }
  void reset();  // after a reconnect: drop partial frames and sequence history

 private:
  // Decodes the frame and calls one typed handler; a failure carries the decoder's message.
  using Route = std::function<Status(const protocol::FrameView&)>;

  void add_route(protocol::MessageId id, Route route);
  void route(const protocol::FrameView& frame);
  void route_typed(const protocol::FrameView& frame);
  void publish_stats();

  const protocol::CodecOptions codec_;
  const std::shared_ptr<protocol::AckOrderSetting> ack_order_;
  std::mutex feed_mutex_;  // one feeder at a time; the parser is not re-entrant
  protocol::FrameParser parser_;
  std::vector<FrameHandler> frame_handlers_;
  std::vector<FrameHandler> routed_handlers_;
  std::vector<DecodeErrorHandler> decode_error_handlers_;
  std::unordered_map<protocol::MessageId, std::vector<Route>> routes_;

  mutable std::mutex stats_mutex_;  // guards published_ only: never held while handlers run
  DispatcherStats published_;
  std::atomic<uint64_t> decode_errors_{0};
  std::atomic<protocol::CrcCoverage> locked_coverage_;
};

template <class Msg>
void Dispatcher::on(std::function<void(const Msg&, const protocol::FrameView&)> handler) {
  add_route(Msg::kId, [this, handler = std::move(handler)](const protocol::FrameView& frame) {
    Result<Msg> message = protocol::decode_payload<Msg>(frame, codec());
    if (!message) return message.status();
    handler(message.value(), frame);
    return Status::ok();
  });
}

}  // namespace k40t::session
