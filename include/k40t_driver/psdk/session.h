// One PSDK link over a k40t::transport::Transport, for either side of it. The driver runs the
// payload role (DJI SKYPORT adapter on the other end); the simulator runs the adapter role.
//
// Incoming commands go to the handler registered for their (set, id). When the command asks for
// an ACK, the handler's reply is sent as the ACK: it echoes the command's sequence, set and id,
// and copies its encryption type (docs/psdk.md#frames). A command nobody handles is answered with
// the single byte 0x02 (unsupported). Incoming ACKs complete our own requests, matched on sequence
// + set + id; a request with no ACK by its deadline completes with a timeout. Our sequence starts
// at 0 and increments per command we send.
//
// Threads: handlers run on the transport's I/O thread and must not block on request() (use
// request_async(), or return nullopt and answer later with send_ack()). request() may be called
// from any other thread. Register handlers before start().
//
// The AES key (derived from the credentials) is held by the session only; nothing here logs it.
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <type_traits>
#include <unordered_map>
#include <vector>

#include "k40t_driver/psdk/aes.h"
#include "k40t_driver/psdk/command.h"
#include "k40t_driver/psdk/frame.h"
#include "k40t_driver/psdk/parser.h"
#include "k40t_driver/psdk/pending_requests.h"
#include "k40t_driver/transport/transport.h"

namespace k40t::psdk {

struct SessionOptions {
  Sender role = Sender::kPayload;
  std::chrono::milliseconds ack_timeout{500};
  // Set to encrypt and decrypt (ENC = 1) frames; without it encrypted frames cannot be read.
  std::optional<AesKey> aes_key;
  // Which of our own commands go out encrypted when a key is set. Empty: the payload role
  // encrypts what docs/psdk.md#frames lists (payload_encrypts()), the adapter role nothing.
  std::function<bool(CommandKey)> encrypt;
};

struct SessionStats {
  ParserStats parser;
  transport::LinkStats link;
  uint64_t commands_received = 0;
  uint64_t acks_sent = 0;
  uint64_t unsupported = 0;     // commands answered 0x02 (or dropped: no ACK requested)
  uint64_t decode_errors = 0;   // commands a typed handler could not decode
  uint64_t decrypt_errors = 0;  // frames whose DATA could not be opened
  uint64_t commands_sent = 0;
  uint64_t acks_received = 0;
  uint64_t ack_timeouts = 0;
  uint64_t late_acks = 0;  // ACKs nothing was waiting for
  uint64_t send_errors = 0;
};

// A command as received: its header and plain DATA (decrypted, padding dropped).
struct IncomingCommand {
  FrameHeader header;
  Data data;
};

class Session {
 public:
  // Returns the ACK's DATA (return code first), or nullopt to send none now.
  using CommandHandler = std::function<std::optional<Data>(const IncomingCommand&)>;
  using FrameHandler = std::function<void(const FrameView&)>;
  using SentHandler = std::function<void(const uint8_t* frame, size_t size)>;

  Session(std::unique_ptr<transport::Transport> transport, SessionOptions options);
  ~Session();  // stop()s
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;

  void on_command(CommandKey key, CommandHandler handler);
  // Typed handler: `handler(const Cmd&)` returns Cmd::Ack (or AckCode / PlainAck for commands
  // whose ACK is the code alone; nothing for commands the document does not ACK). DATA that does
  // not decode is answered 0x01 and counted.
  template <class Cmd, class F>
  void handle(F handler);
  // The dispatch table's keys: every (set, id) a handler is registered for, sorted.
  std::vector<CommandKey> handled_commands() const;
  void on_frame(FrameHandler handler);      // every good frame received (raw rx)
  void on_frame_sent(SentHandler handler);  // every frame written (raw tx)

  Status start();
  void stop();
  bool started() const { return started_; }

  // Sends a command asking for an ACK and waits for it (or the timeout).
  AckResult request_raw(CommandKey key, const uint8_t* data, size_t size);
  // Non-blocking; `done` runs on the I/O thread (ACK) or the session's timer thread (timeout).
  void request_async(CommandKey key, const Data& data, std::function<void(const AckResult&)> done);
  // The decoded ACK (whatever its return code), or a failure: invalid command, not sent, no ACK,
  // ACK that does not decode.
  template <class Cmd>
  Result<typename Cmd::Ack> request(const Cmd& command, AckResult* raw = nullptr);

  // A command that asks for no ACK (pushes, transparent data, floating-window messages).
  Status send_raw(CommandKey key, const uint8_t* data, size_t size);
  template <class Cmd>
  Status send(const Cmd& command);
  // The ACK of `command` (whose header a handler kept), for replies that come later.
  Status send_ack(const FrameHeader& command, const Data& data);

  // Counts a command whose DATA did not decode, for handlers registered with on_command() that
  // decode it themselves (handle() counts its own).
  void note_decode_error() { count(&SessionStats::decode_errors); }

  // Jumps our sequence counter forward (the simulator's sequence-jump fault).
  void skip_sequence(uint16_t count);

  SessionStats stats() const;
  const SessionOptions& options() const { return options_; }
  transport::LinkState link_state() const { return transport_->state(); }

 private:
  void on_bytes(const uint8_t* data, size_t size);
  void on_frame_received(const FrameView& frame);
  void on_command_received(const FrameView& frame, const Data& data);
  void on_ack_received(const FrameView& frame, const Data& data);
  Status send_frame(const FrameHeader& header, const uint8_t* data, size_t size);
  bool should_encrypt(CommandKey key) const;
  uint16_t next_sequence();
  void timer_loop();
  void count(uint64_t SessionStats::*counter);
  static Data code_only(AckCode code);

  std::unique_ptr<transport::Transport> transport_;
  SessionOptions options_;
  std::optional<Aes128Ecb> cipher_;
  std::unordered_map<uint16_t, CommandHandler> handlers_;
  FrameHandler frame_handler_;
  SentHandler sent_handler_;

  FrameParser parser_;  // I/O thread only
  PendingRequests pending_;

  std::mutex send_mutex_;  // one frame at a time on the link, sequence numbers in order
  uint16_t sequence_ = 0;

  mutable std::mutex stats_mutex_;
  SessionStats stats_;

  std::mutex timer_mutex_;
  std::condition_variable timer_wake_;
  std::thread timer_;
  bool stopping_ = false;
  std::atomic<bool> started_{false};
};

// --- templates
// ------------------------------------------------------------------------------------

template <class Cmd, class F>
void Session::handle(F handler) {
  on_command(
      Cmd::key(),
      [this, handler = std::move(handler)](const IncomingCommand& in) -> std::optional<Data> {
        Result<Cmd> command = decode_data<Cmd>(in.data);
        if (!command) {
          count(&SessionStats::decode_errors);
          return code_only(AckCode::kError);
        }
        using Ack = typename Cmd::Ack;
        if constexpr (std::is_same_v<Ack, NoAck>) {
          handler(command.value());
          return std::nullopt;
        } else {
          using Returned = std::decay_t<decltype(handler(command.value()))>;
          if constexpr (std::is_same_v<Returned, AckCode>) {
            return code_only(handler(command.value()));
          } else {
            static_assert(std::is_same_v<Returned, Ack>, "the handler must return Cmd::Ack");
            Result<Data> data = encode_data(handler(command.value()));
            if (!data) return code_only(AckCode::kError);  // our own reply is invalid: say so
            return data.value();
          }
        }
      });
}

template <class Cmd>
Result<typename Cmd::Ack> Session::request(const Cmd& command, AckResult* raw) {
  using Ack = typename Cmd::Ack;
  static_assert(!std::is_same_v<Ack, NoAck>, "the document gives this command no ACK: use send()");
  const Result<Data> data = encode_data(command);
  if (!data) return Result<Ack>::fail(data.error());
  AckResult result = request_raw(Cmd::key(), data->data(), data->size);
  if (raw != nullptr) *raw = result;
  if (!result.received) return Result<Ack>::fail(std::string(Cmd::kName) + ": " + result.message);
  return decode_data<Ack>(result.data);
}

template <class Cmd>
Status Session::send(const Cmd& command) {
  const Result<Data> data = encode_data(command);
  if (!data) return data.status();
  return send_raw(Cmd::key(), data->data(), data->size);
}

}  // namespace k40t::psdk
