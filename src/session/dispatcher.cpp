#include "k40t_driver/session/dispatcher.h"

#include <utility>

namespace k40t::session {

Dispatcher::Dispatcher(protocol::CrcCoverage coverage, const protocol::CodecOptions& codec,
                       std::shared_ptr<protocol::AckOrderSetting> ack_order)
    : codec_(codec),
      ack_order_(ack_order ? std::move(ack_order)
                           : std::make_shared<protocol::AckOrderSetting>(codec)),
      parser_(coverage),
      locked_coverage_(coverage) {
  published_.locked_coverage = coverage;
}

void Dispatcher::on_frame(FrameHandler handler) {
  std::lock_guard<std::mutex> lock(feed_mutex_);
  frame_handlers_.push_back(std::move(handler));
}

void Dispatcher::on_frame_routed(FrameHandler handler) {
  std::lock_guard<std::mutex> lock(feed_mutex_);
  routed_handlers_.push_back(std::move(handler));
}

void Dispatcher::on_decode_error(DecodeErrorHandler handler) {
  std::lock_guard<std::mutex> lock(feed_mutex_);
  decode_error_handlers_.push_back(std::move(handler));
}

void Dispatcher::add_route(protocol::MessageId id, Route route) {
  std::lock_guard<std::mutex> lock(feed_mutex_);
  routes_[id].push_back(std::move(route));
}

void Dispatcher::feed(const uint8_t* data, size_t size) {
  std::lock_guard<std::mutex> lock(feed_mutex_);
  parser_.feed(data, size, [this](const protocol::FrameView& frame) {
    // Publish first, so that a handler reading stats() sees the frame it is handling.
    publish_stats();
    route(frame);
  });
  publish_stats();  // bytes discarded after the last frame, partial frames
}

void Dispatcher::route(const protocol::FrameView& frame) {
  if (protocol::kind_of(frame.header.message_id) == protocol::MessageKind::kAck)
    ack_order_->observe(frame.header.message_id, frame.payload, frame.payload_size);
  for (const FrameHandler& handler : frame_handlers_) handler(frame);
  route_typed(frame);
  for (const FrameHandler& handler : routed_handlers_) handler(frame);
}

void Dispatcher::route_typed(const protocol::FrameView& frame) {
  const auto found = routes_.find(frame.header.message_id);
  if (found == routes_.end()) return;
  for (const Route& typed : found->second) {
    const Status status = typed(frame);
    if (status) continue;
    decode_errors_.fetch_add(1, std::memory_order_relaxed);
    {
      std::lock_guard<std::mutex> lock(stats_mutex_);
      published_.decode_errors = decode_errors_.load(std::memory_order_relaxed);
    }
    for (const DecodeErrorHandler& handler : decode_error_handlers_)
      handler(frame, status.message());
  }
}

void Dispatcher::publish_stats() {
  const protocol::CrcCoverage coverage = parser_.coverage();
  locked_coverage_.store(coverage, std::memory_order_relaxed);
  std::lock_guard<std::mutex> lock(stats_mutex_);
  published_.parser = parser_.stats();
  published_.decode_errors = decode_errors_.load(std::memory_order_relaxed);
  published_.locked_coverage = coverage;
}

const protocol::ParserStats& Dispatcher::parser_stats() const {
  return parser_.stats();
}

size_t Dispatcher::buffered_bytes() const {
  return parser_.buffered_bytes();
}

uint64_t Dispatcher::decode_errors() const {
  return decode_errors_.load(std::memory_order_relaxed);
}

protocol::CrcCoverage Dispatcher::locked_coverage() const {
  return locked_coverage_.load(std::memory_order_relaxed);
}

DispatcherStats Dispatcher::stats() const {
  std::lock_guard<std::mutex> lock(stats_mutex_);
  return published_;
}

void Dispatcher::reset() {
  std::lock_guard<std::mutex> lock(feed_mutex_);
  parser_.reset();
  publish_stats();
}

}  // namespace k40t::session
