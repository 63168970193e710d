// One request/ACK session per link (docs/protocol/decisions.md#a3, A5): frames requests with
// sequence numbers and the right destination, matches ACKs by id (one outstanding request per id; a
// second request for the same id waits its turn), retries on timeout, maps response codes to text,
// routes periodic reports and status frames to typed handlers (through its Dispatcher), and answers
// requests that come from the other side (the pod's 0x000310) through handlers. The same class
// serves the pod role in the simulator: there, handlers answer every request and send_frame() emits
// reports.
//
// Thread-safe: request() may be called from any thread (it blocks that thread only); handlers run
// on the transport's I/O thread and must not block on request() themselves (use request_async()).
// request_async() callbacks run on the session's request thread: they may call request_async()
// again but not request() (that would wait on itself; it fails at once with a message instead).
#pragma once

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "k40t_driver/protocol/ack_order_setting.h"
#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/frame.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/protocol/parser.h"
#include "k40t_driver/session/dispatcher.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::session {

struct SessionOptions {
  protocol::CodecOptions codec;
  protocol::CrcCoverage crc_coverage = protocol::CrcCoverage::kAuto;
  // Source address of what we send: the host (0x01/0x01) for the driver, the camera (0x04/0x01)
  // for the simulated pod.
  protocol::Address own_address = protocol::kHostAddress;
  // The flight controller's address: the pod's GPS requests (0x000310) are answered from it and
  // the laser-target requests (0x000320, section 3.2.4.24) are sent from it.
  protocol::Address flight_controller_address = protocol::kFlightControllerAddress;
  std::chrono::milliseconds ack_timeout{300};
  int retries = 2;  // extra attempts after the first
};

struct SessionStats {
  protocol::ParserStats parser;
  transport::LinkStats link;
  transport::LinkState link_state = transport::LinkState::kClosed;
  uint64_t requests = 0;      // requests whose first attempt was written
  uint64_t acks = 0;          // ACKs matched to an outstanding request (NACKs included)
  uint64_t nacks = 0;         // ACKs whose code is not OK
  uint64_t ack_timeouts = 0;  // requests that got no ACK after all retries
  uint64_t retries = 0;
  uint64_t late_acks = 0;  // ACKs with no outstanding request (after a timeout, duplicates)
  uint64_t frames_sent = 0;
  uint64_t decode_errors = 0;
  uint64_t requests_answered = 0;   // requests from the other side answered by a handler
  uint64_t requests_unhandled = 0;  // requests from the other side with no handler (ignored)
  uint64_t send_errors = 0;         // frames the transport refused
};

// The outcome of one request. Nothing is thrown: validation errors, send failures, timeouts and
// NACKs all come back here with a readable message.
struct AckResult {
  bool ok() const { return received && code == protocol::ResponseCode::kOk; }
  bool sent = false;      // false: validation failed or the link could not send; no bytes left
  bool received = false;  // false: timeout (after retries) or not sent
  protocol::ResponseCode code = protocol::ResponseCode::kTimeout;
  std::string message;           // the pod's response text, or why nothing came back
  std::vector<uint8_t> payload;  // the whole ACK payload, response code included
  int attempts = 0;

  // A request that never reached the wire (invalid arguments, session not running...).
  static AckResult not_sent(std::string why);
};

class Session {
 public:
  using FrameHandler = std::function<void(const protocol::FrameView&)>;
  // Answers a request from the other side: return the ACK payload (response code first), or
  // nullopt to send no ACK (the simulator's dropped-ACK fault uses this).
  using RequestHandler =
      std::function<std::optional<protocol::Payload>(const protocol::FrameView&)>;
  using LinkStateHandler = std::function<void(transport::LinkState, const std::string&)>;

  Session(std::unique_ptr<transport::Transport> transport, SessionOptions options);
  ~Session();  // stop()s

  // Register handlers on dispatcher() and here before start().
  Dispatcher& dispatcher();
  void set_request_handler(protocol::MessageId request_id, RequestHandler handler);
  // Every frame written (raw/tx), in wire order; runs under the send lock, so it must not send.
  // It runs on the writing thread: the session's, the I/O thread (answers to the pod's requests)
  // or the thread of a blocking request() with nothing ahead of it, which writes its own.
  void on_frame_sent(FrameHandler handler);
  void on_link_state(LinkStateHandler handler);

  Status start();  // opens the transport (which connects and reconnects on its own)
  void stop();     // closes the transport; outstanding requests complete with "session stopped"

  // Blocking request with timeout and retries. The destination follows the message family
  // (gimbal ids 0x000001..0x0000FF -> codec.gimbal_address, the pod's flight-controller request
  // 0x000310 -> flight_controller_address, others -> codec.camera_address).
  AckResult request_raw(protocol::MessageId id, const uint8_t* payload, size_t size);
  AckResult request_raw(protocol::MessageId id, const uint8_t* payload, size_t size,
                        protocol::Address destination);
  template <class Req>
  AckResult request(const Req& request);  // validates first: invalid -> sent=false, nothing written
  // The typed ACK (Req::Ack), or a failure carrying AckResult::message.
  template <class Req>
  Result<typename Req::Ack> request_typed(const Req& request, AckResult* raw = nullptr);
  // Non-blocking; `done` runs on an internal thread (at once on the caller's thread when the
  // request is rejected before queueing: invalid payload, session not running).
  void request_async(protocol::MessageId id, const protocol::Payload& payload,
                     std::function<void(const AckResult&)> done);
  void request_async(protocol::MessageId id, const protocol::Payload& payload,
                     protocol::Address destination, std::function<void(const AckResult&)> done);
  protocol::Address destination_of(protocol::MessageId id) const;

  // A frame that is not a request awaiting an ACK (reports and status frames in the simulator,
  // ACKs written by hand). Sequence numbers are the session's, counted per source address.
  Status send_frame(protocol::MessageId id, const uint8_t* payload, size_t size,
                    protocol::Address destination);
  Status send_frame_from(protocol::Address source, protocol::MessageId id, const uint8_t* payload,
                         size_t size, protocol::Address destination);
  template <class Msg>
  Status send_message(const Msg& message, protocol::Address destination);
  // The ACK of a request from the other side, for handlers that answer later than their call
  // (the simulator's delayed ACKs): from the address the request was sent to, to its sender.
  Status send_ack(const protocol::FrameHeader& request, const uint8_t* payload, size_t size);

  SessionStats stats() const;
  transport::LinkState link_state() const;
  // As configured; options().codec.ack_byte_order is the start of an `auto` order.
  const SessionOptions& options() const;
  // The codec options in force now: ack_byte_order as the pod's ACKs showed it (auto), else as
  // configured. Every typed encode and decode of the session uses these.
  protocol::CodecOptions codec() const;
  const protocol::AckOrderSetting& ack_order() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

template <class Req>
AckResult Session::request(const Req& request) {
  Result<protocol::Payload> payload = protocol::encode_payload(request, codec());
  if (!payload) return AckResult::not_sent(payload.error());
  return request_raw(Req::kId, payload->data(), payload->size);
}

template <class Req>
Result<typename Req::Ack> Session::request_typed(const Req& request, AckResult* raw) {
  using Ack = typename Req::Ack;
  AckResult result = this->request(request);
  if (!result.ok()) {
    if (raw != nullptr) *raw = result;
    return Result<Ack>::fail(result.message);
  }
  Result<Ack> ack =
      protocol::decode_payload<Ack>(result.payload.data(), result.payload.size(), codec());
  if (raw != nullptr) *raw = std::move(result);
  return ack;
}

template <class Msg>
Status Session::send_message(const Msg& message, protocol::Address destination) {
  Result<protocol::Payload> payload = protocol::encode_payload(message, codec());
  if (!payload) return payload.status();
  return send_frame(Msg::kId, payload->data(), payload->size, destination);
}

}  // namespace k40t::session
