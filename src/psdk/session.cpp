#include "k40t_driver/psdk/session.h"

#include <algorithm>
#include <cstring>
#include <future>

#include "k40t_driver/psdk/catalogue.h"
#include "k40t_driver/transport/thread_name.h"

namespace k40t::psdk {

Session::Session(std::unique_ptr<transport::Transport> transport, SessionOptions options)
    : transport_(std::move(transport)), options_(std::move(options)) {
  if (options_.aes_key) cipher_.emplace(*options_.aes_key);
  if (!options_.encrypt) {
    if (options_.role == Sender::kPayload)
      options_.encrypt = &payload_encrypts;
    else
      options_.encrypt = [](CommandKey) { return false; };
  }
}

Session::~Session() {
  stop();
}

void Session::on_command(CommandKey key, CommandHandler handler) {
  handlers_[key.packed()] = std::move(handler);
}
std::vector<CommandKey> Session::handled_commands() const {
  std::vector<CommandKey> keys;
  keys.reserve(handlers_.size());
  for (const auto& entry : handlers_)
    keys.push_back({static_cast<uint8_t>(entry.first >> 8), static_cast<uint8_t>(entry.first)});
  std::sort(keys.begin(), keys.end());
  return keys;
}
void Session::on_frame(FrameHandler handler) {
  frame_handler_ = std::move(handler);
}
void Session::on_frame_sent(SentHandler handler) {
  sent_handler_ = std::move(handler);
}

Status Session::start() {
  if (started_) return Status::ok();
  transport_->set_receive_callback(
      [this](const uint8_t* data, size_t size) { on_bytes(data, size); });
  transport_->set_state_callback([this](transport::LinkState state, const std::string&) {
    // A new connection starts a new byte stream: a partial frame of the old one means nothing.
    if (state == transport::LinkState::kConnected) parser_.reset();
  });
  {
    std::lock_guard<std::mutex> lock(timer_mutex_);
    stopping_ = false;
  }
  timer_ = std::thread([this] { timer_loop(); });
  const Status opened = transport_->open();
  if (!opened) {
    {
      std::lock_guard<std::mutex> lock(timer_mutex_);
      stopping_ = true;
    }
    timer_wake_.notify_all();
    timer_.join();
    return opened;
  }
  started_ = true;
  return Status::ok();
}

void Session::stop() {
  if (!started_.exchange(false)) return;
  transport_->close();
  {
    std::lock_guard<std::mutex> lock(timer_mutex_);
    stopping_ = true;
  }
  timer_wake_.notify_all();
  if (timer_.joinable()) timer_.join();
  for (auto& e : pending_.take_all()) {
    AckResult r;
    r.sent = true;
    r.sequence = e.sequence;
    r.message = "session stopped before the ACK arrived";
    e.done(r);
  }
}

void Session::count(uint64_t SessionStats::*counter) {
  std::lock_guard<std::mutex> lock(stats_mutex_);
  ++(stats_.*counter);
}

Data Session::code_only(AckCode code) {
  Data d;
  d.bytes[0] = static_cast<uint8_t>(code);
  d.size = 1;
  return d;
}

SessionStats Session::stats() const {
  SessionStats s;
  {
    std::lock_guard<std::mutex> lock(stats_mutex_);
    s = stats_;
  }
  s.link = transport_->stats();
  return s;
}

// --- receiving
// ------------------------------------------------------------------------------------

void Session::on_bytes(const uint8_t* data, size_t size) {
  parser_.feed(data, size, [this](const FrameView& frame) { on_frame_received(frame); });
  std::lock_guard<std::mutex> lock(stats_mutex_);
  stats_.parser = parser_.stats();
}

void Session::on_frame_received(const FrameView& frame) {
  if (frame_handler_) frame_handler_(frame);
  const Result<Data> data = open_data(frame, cipher_ ? &*cipher_ : nullptr);
  if (!data) {
    // Unreadable DATA (an encrypted frame without the key, bad padding): nothing to answer with
    // confidence, so the frame is counted and dropped.
    count(&SessionStats::decrypt_errors);
    return;
  }
  if (frame.header.packet_type == PacketType::kAck)
    on_ack_received(frame, data.value());
  else
    on_command_received(frame, data.value());
}

void Session::on_command_received(const FrameView& frame, const Data& data) {
  count(&SessionStats::commands_received);
  const bool wants_ack = frame.header.ack_request != AckRequest::kNoAck;
  auto it = handlers_.find(frame.header.command.packed());
  if (it == handlers_.end()) {
    count(&SessionStats::unsupported);
    if (wants_ack) send_ack(frame.header, code_only(AckCode::kUnsupported));
    return;
  }
  IncomingCommand in;
  in.header = frame.header;
  in.data = data;
  const std::optional<Data> reply = it->second(in);
  if (reply && wants_ack) send_ack(frame.header, *reply);
}

void Session::on_ack_received(const FrameView& frame, const Data& data) {
  std::optional<PendingRequests::Callback> done =
      pending_.take(frame.header.command, frame.header.sequence);
  if (!done) {
    count(&SessionStats::late_acks);
    return;
  }
  count(&SessionStats::acks_received);
  AckResult r;
  r.sent = true;
  r.received = true;
  r.data = data;
  r.sequence = frame.header.sequence;
  r.message = data.size > 0 ? ack_code_text(data.bytes[0]) : "ACK without a return code";
  (*done)(r);
}

// --- sending
// --------------------------------------------------------------------------------------

bool Session::should_encrypt(CommandKey key) const {
  return cipher_.has_value() && options_.encrypt(key);
}

Status Session::send_frame(const FrameHeader& header, const uint8_t* data, size_t size) {
  const Result<EncodedFrame> frame =
      encode_frame(header, data, size, cipher_ ? &*cipher_ : nullptr);
  if (!frame) {
    count(&SessionStats::send_errors);
    return frame.status();
  }
  const Status sent = transport_->send(frame->data(), frame->size());
  if (!sent) {
    count(&SessionStats::send_errors);
    return sent;
  }
  if (sent_handler_) sent_handler_(frame->data(), frame->size());
  return Status::ok();
}

Status Session::send_ack(const FrameHeader& command, const Data& data) {
  FrameHeader h;
  h.packet_type = PacketType::kAck;
  h.ack_request = AckRequest::kNoAck;
  h.encryption = command.encryption;  // an ACK copies the command's encryption type
  h.command = command.command;
  h.sequence = command.sequence;
  const Status sent = send_frame(h, data.data(), data.size);
  if (sent) count(&SessionStats::acks_sent);
  return sent;
}

uint16_t Session::next_sequence() {
  return sequence_++;
}

void Session::skip_sequence(uint16_t count) {
  std::lock_guard<std::mutex> lock(send_mutex_);
  sequence_ = static_cast<uint16_t>(sequence_ + count);
}

Status Session::send_raw(CommandKey key, const uint8_t* data, size_t size) {
  FrameHeader h;
  h.command = key;
  h.encryption = should_encrypt(key) ? Encryption::kAes : Encryption::kNone;
  std::lock_guard<std::mutex> lock(send_mutex_);
  h.sequence = next_sequence();
  const Status sent = send_frame(h, data, size);
  if (sent) count(&SessionStats::commands_sent);
  return sent;
}

void Session::request_async(CommandKey key, const Data& data,
                            std::function<void(const AckResult&)> done) {
  AckResult failed;
  if (!started_) {
    failed.message = "session not started";
    done(failed);
    return;
  }
  FrameHeader h;
  h.command = key;
  h.ack_request = AckRequest::kAfterExecution;
  h.encryption = should_encrypt(key) ? Encryption::kAes : Encryption::kNone;
  Status sent = Status::ok();
  {
    std::lock_guard<std::mutex> lock(send_mutex_);
    h.sequence = next_sequence();
    // Registered before the bytes leave, so an instant ACK finds it.
    pending_.add(key, h.sequence, PendingRequests::Clock::now() + options_.ack_timeout, done);
    sent = send_frame(h, data.data(), data.size);
    if (!sent) pending_.cancel(key, h.sequence);
  }
  if (!sent) {
    failed.sequence = h.sequence;
    failed.message = sent.message();
    done(failed);
    return;
  }
  count(&SessionStats::commands_sent);
  // A new, possibly earliest, deadline. Taking the timer's lock first means the timer thread is
  // either waiting (and gets the notification) or has not yet read the deadlines (and sees it).
  { std::lock_guard<std::mutex> lock(timer_mutex_); }
  timer_wake_.notify_all();
}

AckResult Session::request_raw(CommandKey key, const uint8_t* data, size_t size) {
  if (size > kMaxDataSize) {
    AckResult r;
    r.message = "DATA of " + std::to_string(size) + " bytes exceeds the maximum of 256";
    return r;
  }
  Data d;
  if (size > 0) std::memcpy(d.bytes.data(), data, size);
  d.size = size;
  auto promise = std::make_shared<std::promise<AckResult>>();
  std::future<AckResult> future = promise->get_future();
  request_async(key, d, [promise](const AckResult& r) { promise->set_value(r); });
  return future.get();
}

void Session::timer_loop() {
  transport::name_this_thread("k40t_psdk_tmr");
  std::unique_lock<std::mutex> lock(timer_mutex_);
  while (!stopping_) {
    const auto next = pending_.next_deadline();
    if (next)
      timer_wake_.wait_until(lock, *next);
    else
      timer_wake_.wait(lock);
    if (stopping_) break;
    lock.unlock();
    for (auto& e : pending_.take_expired(PendingRequests::Clock::now())) {
      count(&SessionStats::ack_timeouts);
      AckResult r;
      r.sent = true;
      r.sequence = e.sequence;
      r.message = "no ACK within " + std::to_string(options_.ack_timeout.count()) + " ms";
      e.done(r);
    }
    lock.lock();
  }
}

}  // namespace k40t::psdk
