// The request side of a session (docs/protocol/decisions.md#a5): one outstanding request per
// message id, the others for that id queued behind it; ACKs matched by id; timeouts and retries;
// AckResult messages. A request whose repeat would repeat an action (protocol/repeat_safety.h) is
// written once and waited for as long as all the attempts would take (longer for a pod that
// answers only once the action is done: protocol::done_ack_wait()). It owns the thread that
// writes attempts, watches deadlines and runs completion callbacks, so that the transport's I/O
// thread never waits on the link, nor an asynchronous caller; a blocking call() with nothing
// ahead of it writes its own first attempt (it waits for the answer anyway).
#pragma once

#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <unordered_map>
#include <vector>

#include "k40t_driver/protocol/ack_order_setting.h"
#include "k40t_driver/protocol/codec_options.h"
#include "k40t_driver/protocol/message.h"
#include "k40t_driver/session/session.h"

namespace k40t::session {

class RequestTracker {
 public:
  using Clock = std::chrono::steady_clock;
  using Done = std::function<void(const AckResult&)>;
  // Writes one attempt; called on the tracker's thread with no lock held.
  using SendAttempt = std::function<Status(protocol::MessageId id, const protocol::Payload& payload,
                                           protocol::Address destination)>;

  struct Counters {
    uint64_t requests = 0;
    uint64_t acks = 0;
    uint64_t nacks = 0;
    uint64_t ack_timeouts = 0;
    uint64_t retries = 0;
    uint64_t late_acks = 0;
  };

  // `ack_order`: the link's ACK byte order, read as each ACK's response code is decoded.
  RequestTracker(SendAttempt send, std::chrono::milliseconds ack_timeout, int retries,
                 const protocol::CodecOptions& codec,
                 std::shared_ptr<const protocol::AckOrderSetting> ack_order);
  ~RequestTracker();  // stop()s
  RequestTracker(const RequestTracker&) = delete;
  RequestTracker& operator=(const RequestTracker&) = delete;

  void start();
  // Completes every queued and outstanding request with `why` and joins the thread.
  void stop(const std::string& why);

  // Queues a request; `done` runs on the tracker's thread (on the caller's, at once, when the
  // tracker is not running).
  void submit(protocol::MessageId id, const protocol::Payload& payload,
              protocol::Address destination, Done done);
  // Blocking form. Fails at once when called on the tracker's own thread (it would wait on itself).
  // When nothing for its id is outstanding or queued, the caller writes the request itself (the
  // tracker's thread then only watches its deadline): one thread hand-over less before the wire.
  AckResult call(protocol::MessageId id, const protocol::Payload& payload,
                 protocol::Address destination);

  // An ACK from the link (I/O thread): true if it completed an outstanding request, false if no
  // request for its id was outstanding (counted as late). The ACK of a blocking call() completes
  // it here (its AckResult is built here); any other is handed to the tracker's thread.
  bool on_ack(protocol::MessageId ack_id, const uint8_t* payload, size_t size);

  Counters counters() const;

 private:
  struct Pending {
    protocol::MessageId id = 0;
    protocol::Payload payload;
    protocol::Address destination;
    Done done;
    AckResult result;
    bool once = false;    // not repeat-safe (protocol/repeat_safety.h): one attempt, a long wait
    uint64_t serial = 0;  // which request an attempt is of
    bool caller_waits = false;  // call()'s: its ACK completes it on the I/O thread, at once
  };
  enum class SlotState { kIdle, kSending, kWaiting, kAcked };
  // One per request id: queue.front() is the outstanding request whenever state != kIdle.
  struct Slot {
    std::deque<Pending> queue;
    SlotState state = SlotState::kIdle;
    Clock::time_point deadline;
    protocol::Payload ack;
    bool caller_sending = false;  // call() is writing the front request: the thread leaves it
  };
  struct Attempt {
    protocol::MessageId id = 0;
    protocol::Payload payload;
    protocol::Address destination;
    Status status = Status::ok();
    uint64_t serial = 0;
  };
  struct Finished {
    Done done;
    AckResult result;
  };

  void run();
  void step(Slot& slot, Clock::time_point now);
  void queue_for_thread(protocol::MessageId id, const protocol::Payload& payload,
                        protocol::Address destination, Done done, bool caller_waits);
  Pending& enqueue(Slot& slot, protocol::MessageId id, const protocol::Payload& payload,
                   protocol::Address destination, Done done);
  Attempt begin_attempt(Slot& slot);
  void start_attempt(Slot& slot);
  void after_attempt(const Attempt& attempt, Clock::time_point now,
                     std::vector<Finished>& finished);
  void finish_front(Slot& slot, std::vector<Finished>& finished);
  void complete_with_ack(Slot& slot, std::vector<Finished>& finished);
  void fail_everything();
  std::string not_repeated_message(protocol::MessageId id) const;
  // How long a request sent once waits for its ACK.
  std::chrono::milliseconds once_wait(protocol::MessageId id) const;

  const SendAttempt send_;
  const std::chrono::milliseconds ack_timeout_;
  const int max_attempts_;
  const protocol::CodecOptions codec_;
  const std::shared_ptr<const protocol::AckOrderSetting> ack_order_;

  mutable std::mutex mutex_;
  std::condition_variable wake_;
  std::unordered_map<protocol::MessageId, Slot> slots_;
  bool running_ = false;
  bool stopping_ = false;
  std::string stop_reason_;
  std::thread thread_;
  std::atomic<std::thread::id> thread_id_{};
  std::vector<Attempt> attempts_;   // filled under the lock, written without it
  std::vector<Finished> finished_;  // callbacks to run without the lock (the thread's alone)
  uint64_t next_serial_ = 0;
  Counters counters_;
};

}  // namespace k40t::session
