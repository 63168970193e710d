#include "k40t_driver/session/session.h"

#include <mutex>
#include <unordered_map>
#include <utility>

#include "frame_sender.h"
#include "k40t_driver/protocol/catalogue.h"
#include "request_tracker.h"

namespace k40t::session {

AckResult AckResult::not_sent(std::string why) {
  AckResult result;
  result.sent = false;
  result.received = false;
  result.code = protocol::ResponseCode::kFailure;
  result.message = std::move(why);
  return result;
}

namespace {
// The pod's request for GPS data, addressed to the flight controller (section 3.2.4.15).
constexpr protocol::MessageId kGpsRequestId = 0x000310;
constexpr protocol::MessageId kTargetGpsRequestId = 0x000320;
constexpr bool is_gimbal_id(protocol::MessageId id) {
  const protocol::MessageId request = protocol::request_id_of(id);
  return request >= 0x000001 && request <= 0x0000FF;
}
}  // namespace

struct Session::Impl {
  Impl(std::unique_ptr<transport::Transport> link, SessionOptions opts)
      : options(std::move(opts)),
        ack_order(std::make_shared<protocol::AckOrderSetting>(options.codec)),
        transport(std::move(link)),
        dispatcher(options.crc_coverage, options.codec, ack_order),
        sender(transport.get(), options.crc_coverage, dispatcher),
        tracker(
            [this](protocol::MessageId id, const protocol::Payload& payload, protocol::Address to) {
              return sender.send(id, payload.data(), payload.size, request_source(id), to);
            },
            options.ack_timeout, options.retries, options.codec, ack_order) {
    // After every observer of the frame: the caller of a request wakes to a driver that has
    // seen its ACK.
    dispatcher.on_frame_routed([this](const protocol::FrameView& frame) { handle_frame(frame); });
  }

  void handle_frame(const protocol::FrameView& frame);
  void answer_request(const protocol::FrameView& frame);
  protocol::Address reply_source(const protocol::FrameHeader& request) const;
  protocol::Address request_source(protocol::MessageId id) const;
  void handle_link_state(transport::LinkState state, const std::string& reason);

  const SessionOptions options;
  // Shared by the dispatcher (which updates it) and the tracker (ack_byte_order: auto).
  const std::shared_ptr<protocol::AckOrderSetting> ack_order;
  std::unique_ptr<transport::Transport> transport;
  Dispatcher dispatcher;
  FrameSender sender;
  RequestTracker tracker;
  std::unordered_map<protocol::MessageId, RequestHandler> request_handlers;
  std::vector<LinkStateHandler> link_state_handlers;
  std::atomic<uint64_t> requests_answered{0};
  std::atomic<uint64_t> requests_unhandled{0};

  std::mutex lifecycle_mutex;  // start()/stop()
  bool started = false;
};

void Session::Impl::handle_frame(const protocol::FrameView& frame) {
  const protocol::MessageId id = frame.header.message_id;
  switch (protocol::kind_of(id)) {
    case protocol::MessageKind::kAck:
      tracker.on_ack(id, frame.payload, frame.payload_size);  // a late ACK is counted there
      break;
    case protocol::MessageKind::kRequestOrReport:
      if (!protocol::is_periodic_report(id)) answer_request(frame);
      break;
    default:
      break;  // status frames and others: typed routing only
  }
}

void Session::Impl::answer_request(const protocol::FrameView& frame) {
  const auto found = request_handlers.find(frame.header.message_id);
  if (found == request_handlers.end()) {
    requests_unhandled.fetch_add(1, std::memory_order_relaxed);
    return;
  }
  const std::optional<protocol::Payload> ack = found->second(frame);
  if (!ack) return;  // the handler chose not to answer
  // Counted before the write, so that whoever receives the ACK finds it counted already.
  requests_answered.fetch_add(1, std::memory_order_relaxed);
  const Status sent = sender.send(protocol::ack_id_of(frame.header.message_id), ack->data(),
                                  ack->size, reply_source(frame.header), frame.header.source);
  if (!sent) requests_answered.fetch_sub(1, std::memory_order_relaxed);  // in send_errors instead
}

// The ACK comes from the address the request was sent to (the gimbal's 0x03 or the camera's 0x04
// in the simulator), except that the pod's GPS request is answered from the flight controller's
// address, whatever it was sent to; an unaddressed request (system 0) from our own address.
protocol::Address Session::Impl::reply_source(const protocol::FrameHeader& request) const {
  if (request.message_id == kGpsRequestId) return options.flight_controller_address;
  if (request.destination.system == 0) return options.own_address;
  return request.destination;
}

// Section 3.2.4.24: the laser-target request 0x000320 is the flight controller's (0x02/0x01), as
// the pod's GPS request 0x000310 is answered from there; everything else is the host's.
protocol::Address Session::Impl::request_source(protocol::MessageId id) const {
  if (id == kTargetGpsRequestId) return options.flight_controller_address;
  return options.own_address;
}

void Session::Impl::handle_link_state(transport::LinkState state, const std::string& reason) {
  // A new connection starts a new byte stream: a partial frame or the sequence history of the
  // old one would only produce false errors.
  if (state == transport::LinkState::kConnected) dispatcher.reset();
  for (const LinkStateHandler& handler : link_state_handlers) handler(state, reason);
}

Session::Session(std::unique_ptr<transport::Transport> transport, SessionOptions options)
    : impl_(std::make_unique<Impl>(std::move(transport), std::move(options))) {}

Session::~Session() {
  stop();
}

Dispatcher& Session::dispatcher() {
  return impl_->dispatcher;
}

void Session::set_request_handler(protocol::MessageId request_id, RequestHandler handler) {
  impl_->request_handlers[request_id] = std::move(handler);
}

void Session::on_frame_sent(FrameHandler handler) {
  impl_->sender.on_frame_sent(std::move(handler));
}

void Session::on_link_state(LinkStateHandler handler) {
  impl_->link_state_handlers.push_back(std::move(handler));
}

Status Session::start() {
  std::lock_guard<std::mutex> lock(impl_->lifecycle_mutex);
  if (impl_->started) return Status::fail("session already started");
  if (!impl_->transport) return Status::fail("session has no transport");
  Impl* impl = impl_.get();
  impl->transport->set_receive_callback(
      [impl](const uint8_t* data, size_t size) { impl->dispatcher.feed(data, size); });
  impl->transport->set_state_callback(
      [impl](transport::LinkState state, const std::string& reason) {
        impl->handle_link_state(state, reason);
      });
  impl->tracker.start();
  const Status opened = impl->transport->open();
  if (!opened) {
    impl->tracker.stop("the transport did not open");
    return Status::fail(impl->transport->url() + ": " + opened.message());
  }
  impl->started = true;
  return Status::ok();
}

void Session::stop() {
  std::lock_guard<std::mutex> lock(impl_->lifecycle_mutex);
  if (!impl_->started) return;
  impl_->transport->close();
  impl_->tracker.stop("session stopped");
  impl_->started = false;
}

protocol::Address Session::destination_of(protocol::MessageId id) const {
  if (protocol::request_id_of(id) == kGpsRequestId) return impl_->options.flight_controller_address;
  return is_gimbal_id(id) ? impl_->options.codec.gimbal_address
                          : impl_->options.codec.camera_address;
}

AckResult Session::request_raw(protocol::MessageId id, const uint8_t* payload, size_t size) {
  return request_raw(id, payload, size, destination_of(id));
}

namespace {
// What makes a request unsendable before it is queued: nothing is written then.
Status check_request(protocol::MessageId id, size_t size) {
  if (id > 0xFFFF) {
    return Status::fail(protocol::display_name(id) +
                        " is not a request: request ids have high byte 0x00 (section 2.1)");
  }
  if (size > protocol::kMaxPayloadSize) {
    return Status::fail(protocol::display_name(id) + ": payload of " + std::to_string(size) +
                        " bytes exceeds the frame maximum of 243 (section 2.1)");
  }
  return Status::ok();
}

protocol::Payload to_payload(const uint8_t* data, size_t size) {
  protocol::Payload payload;
  std::copy(data, data + size, payload.bytes.begin());
  payload.size = size;
  return payload;
}
}  // namespace

AckResult Session::request_raw(protocol::MessageId id, const uint8_t* payload, size_t size,
                               protocol::Address destination) {
  const Status valid = check_request(id, size);
  if (!valid) return AckResult::not_sent(valid.message());
  return impl_->tracker.call(id, to_payload(payload, size), destination);
}

void Session::request_async(protocol::MessageId id, const protocol::Payload& payload,
                            std::function<void(const AckResult&)> done) {
  request_async(id, payload, destination_of(id), std::move(done));
}

void Session::request_async(protocol::MessageId id, const protocol::Payload& payload,
                            protocol::Address destination,
                            std::function<void(const AckResult&)> done) {
  const Status valid = check_request(id, payload.size);
  if (!valid) {
    done(AckResult::not_sent(valid.message()));
    return;
  }
  impl_->tracker.submit(id, payload, destination, std::move(done));
}

Status Session::send_frame(protocol::MessageId id, const uint8_t* payload, size_t size,
                           protocol::Address destination) {
  return send_frame_from(impl_->options.own_address, id, payload, size, destination);
}

Status Session::send_frame_from(protocol::Address source, protocol::MessageId id,
                                const uint8_t* payload, size_t size,
                                protocol::Address destination) {
  return impl_->sender.send(id, payload, size, source, destination);
}

Status Session::send_ack(const protocol::FrameHeader& request, const uint8_t* payload,
                         size_t size) {
  return impl_->sender.send(protocol::ack_id_of(request.message_id), payload, size,
                            impl_->reply_source(request), request.source);
}

SessionStats Session::stats() const {
  SessionStats s;
  const DispatcherStats d = impl_->dispatcher.stats();
  s.parser = d.parser;
  s.decode_errors = d.decode_errors;
  if (impl_->transport) {
    s.link = impl_->transport->stats();
    s.link_state = impl_->transport->state();
  }
  const RequestTracker::Counters c = impl_->tracker.counters();
  s.requests = c.requests;
  s.acks = c.acks;
  s.nacks = c.nacks;
  s.ack_timeouts = c.ack_timeouts;
  s.retries = c.retries;
  s.late_acks = c.late_acks;
  s.frames_sent = impl_->sender.frames_sent();
  s.send_errors = impl_->sender.send_errors();
  s.requests_answered = impl_->requests_answered.load(std::memory_order_relaxed);
  s.requests_unhandled = impl_->requests_unhandled.load(std::memory_order_relaxed);
  return s;
}

transport::LinkState Session::link_state() const {
  return impl_->transport ? impl_->transport->state() : transport::LinkState::kClosed;
}

const SessionOptions& Session::options() const {
  return impl_->options;
}

protocol::CodecOptions Session::codec() const {
  return impl_->ack_order->codec_with(impl_->options.codec);
}

const protocol::AckOrderSetting& Session::ack_order() const {
  return *impl_->ack_order;
}

}  // namespace k40t::session
