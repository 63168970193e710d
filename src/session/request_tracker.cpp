#include "request_tracker.h"

#include <algorithm>
#include <cstdio>
#include <memory>
#include <utility>

#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/messages/ack.h"
#include "k40t_driver/protocol/repeat_safety.h"
#include "k40t_driver/transport/thread_name.h"

namespace k40t::session {

namespace {

std::string code_hex(uint16_t code) {
  char buffer[16];
  std::snprintf(buffer, sizeof(buffer), "0x%04X", code);
  return buffer;
}

}  // namespace

std::chrono::milliseconds RequestTracker::once_wait(protocol::MessageId id) const {
  return std::max<std::chrono::milliseconds>(ack_timeout_ * max_attempts_,
                                             protocol::done_ack_wait(id, codec_.conventions));
}

std::string RequestTracker::not_repeated_message(protocol::MessageId id) const {
  return "no ACK for " + protocol::display_name(id) + " within " +
         std::to_string(once_wait(id).count()) +
         " ms; not sent again, since a repeat would repeat the action: the pod may have done it "
         "(see its status reports)";
}

RequestTracker::RequestTracker(SendAttempt send, std::chrono::milliseconds ack_timeout, int retries,
                               const protocol::CodecOptions& codec,
                               std::shared_ptr<const protocol::AckOrderSetting> ack_order)
    : send_(std::move(send)),
      ack_timeout_(ack_timeout),
      max_attempts_(1 + std::max(retries, 0)),
      codec_(codec),
      ack_order_(std::move(ack_order)) {}

RequestTracker::~RequestTracker() {
  stop("session stopped");
}

void RequestTracker::start() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (running_) return;
  running_ = true;
  stopping_ = false;
  thread_ = std::thread([this] { run(); });
  thread_id_ = thread_.get_id();
}

void RequestTracker::stop(const std::string& why) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!running_) return;
    stopping_ = true;
    stop_reason_ = why;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
  std::lock_guard<std::mutex> lock(mutex_);
  running_ = false;
  thread_id_ = std::thread::id();
}

void RequestTracker::submit(protocol::MessageId id, const protocol::Payload& payload,
                            protocol::Address destination, Done done) {
  queue_for_thread(id, payload, destination, std::move(done), false);
}

void RequestTracker::queue_for_thread(protocol::MessageId id, const protocol::Payload& payload,
                                      protocol::Address destination, Done done, bool caller_waits) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (!running_ || stopping_) {
    lock.unlock();
    done(AckResult::not_sent(protocol::display_name(id) + " not sent: the session is not running"));
    return;
  }
  enqueue(slots_[protocol::request_id_of(id)], id, payload, destination, std::move(done))
      .caller_waits = caller_waits;
  lock.unlock();
  wake_.notify_all();
}

RequestTracker::Pending& RequestTracker::enqueue(Slot& slot, protocol::MessageId id,
                                                 const protocol::Payload& payload,
                                                 protocol::Address destination, Done done) {
  Pending pending;
  pending.id = id;
  pending.payload = payload;
  pending.destination = destination;
  pending.done = std::move(done);
  pending.once = !protocol::repeat_safe(id, payload.data(), payload.size);
  pending.serial = ++next_serial_;
  slot.queue.push_back(std::move(pending));
  return slot.queue.back();
}

AckResult RequestTracker::call(protocol::MessageId id, const protocol::Payload& payload,
                               protocol::Address destination) {
  if (std::this_thread::get_id() == thread_id_.load()) {
    return AckResult::not_sent(protocol::display_name(id) +
                               " not sent: request() called from a request_async() callback would "
                               "wait on itself; use request_async() there");
  }
  struct Waiter {
    std::mutex mutex;
    std::condition_variable done_cv;
    bool done = false;
    AckResult result;
  };
  auto waiter = std::make_shared<Waiter>();
  Done done = [waiter](const AckResult& result) {
    std::lock_guard<std::mutex> lock(waiter->mutex);
    waiter->result = result;
    waiter->done = true;
    waiter->done_cv.notify_all();
  };
  std::unique_lock<std::mutex> tracker_lock(mutex_);
  Slot& slot = slots_[protocol::request_id_of(id)];  // stays put: unordered_map nodes do not move
  if (!running_ || stopping_ || slot.state != SlotState::kIdle || !slot.queue.empty()) {
    tracker_lock.unlock();
    queue_for_thread(id, payload, destination, std::move(done), true);
  } else {
    // Nothing ahead of it: written from here rather than by the tracker's thread, which would
    // have to be woken first; the thread leaves the slot alone until after_attempt() is done.
    enqueue(slot, id, payload, destination, std::move(done)).caller_waits = true;
    Attempt attempt = begin_attempt(slot);
    slot.caller_sending = true;
    tracker_lock.unlock();
    attempt.status = send_(attempt.id, attempt.payload, attempt.destination);
    tracker_lock.lock();
    slot.caller_sending = false;
    std::vector<Finished> finished;  // a failed write; finished_ is the thread's alone
    after_attempt(attempt, Clock::now(), finished);
    tracker_lock.unlock();
    wake_.notify_all();  // its deadline, or an ACK that came during the write
    for (Finished& f : finished) f.done(f.result);
  }
  std::unique_lock<std::mutex> lock(waiter->mutex);
  waiter->done_cv.wait(lock, [&] { return waiter->done; });
  return std::move(waiter->result);
}

bool RequestTracker::on_ack(protocol::MessageId ack_id, const uint8_t* payload, size_t size) {
  std::unique_lock<std::mutex> lock(mutex_);
  const auto found = slots_.find(protocol::request_id_of(ack_id));
  // kSending counts as outstanding: the pod may answer before send() has returned.
  if (found == slots_.end() ||
      (found->second.state != SlotState::kSending && found->second.state != SlotState::kWaiting)) {
    ++counters_.late_acks;
    return false;
  }
  Slot& slot = found->second;
  const bool written = slot.state == SlotState::kWaiting;  // and after_attempt() done with it
  const size_t n = std::min(size, slot.ack.bytes.size());
  std::copy(payload, payload + n, slot.ack.bytes.begin());
  slot.ack.size = n;
  slot.state = SlotState::kAcked;
  if (!written || !slot.queue.front().caller_waits) {
    lock.unlock();
    wake_.notify_all();
    return true;
  }
  // A blocking call() is waiting: completed here rather than by the tracker's thread, which would
  // have to be woken first (one thread hand-over less). Its callback only wakes the caller.
  std::vector<Finished> finished;  // finished_ is the thread's alone
  complete_with_ack(slot, finished);
  const bool more = !slot.queue.empty();
  lock.unlock();
  if (more) wake_.notify_all();  // the next request for this id
  for (Finished& f : finished) f.done(f.result);
  return true;
}

RequestTracker::Counters RequestTracker::counters() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return counters_;
}

void RequestTracker::run() {
  transport::name_this_thread("k40t_sess");
  std::unique_lock<std::mutex> lock(mutex_);
  while (!stopping_) {
    const Clock::time_point now = Clock::now();
    Clock::time_point next_deadline = Clock::time_point::max();
    for (auto& entry : slots_) {
      Slot& slot = entry.second;
      step(slot, now);
      if (slot.state == SlotState::kWaiting) next_deadline = std::min(next_deadline, slot.deadline);
    }
    if (attempts_.empty() && finished_.empty()) {
      if (next_deadline == Clock::time_point::max()) {
        wake_.wait(lock);
      } else {
        wake_.wait_until(lock, next_deadline);
      }
      continue;
    }
    // Callbacks and writes happen without the lock, so ACKs keep flowing meanwhile.
    lock.unlock();
    for (Finished& f : finished_) f.done(f.result);
    for (Attempt& a : attempts_) a.status = send_(a.id, a.payload, a.destination);
    lock.lock();
    finished_.clear();
    const Clock::time_point sent_at = Clock::now();
    for (const Attempt& a : attempts_) after_attempt(a, sent_at, finished_);
    attempts_.clear();
  }
  fail_everything();
  lock.unlock();
  for (Finished& f : finished_) f.done(f.result);
  finished_.clear();
}

void RequestTracker::step(Slot& slot, Clock::time_point now) {
  if (slot.caller_sending) return;  // call() writes it and then takes it back
  if (slot.state == SlotState::kAcked) {
    complete_with_ack(slot, finished_);
  } else if (slot.state == SlotState::kWaiting && slot.deadline <= now) {
    Pending& pending = slot.queue.front();
    if (!pending.once && pending.result.attempts < max_attempts_) {
      ++counters_.retries;
      start_attempt(slot);
    } else {
      ++counters_.ack_timeouts;
      pending.result.received = false;
      pending.result.code = protocol::ResponseCode::kTimeout;
      pending.result.message =
          pending.once ? not_repeated_message(pending.id)
                       : "no ACK for " + protocol::display_name(pending.id) + " after " +
                             std::to_string(pending.result.attempts) +
                             (pending.result.attempts == 1 ? " attempt" : " attempts") +
                             " (timeout " + std::to_string(ack_timeout_.count()) + " ms each)";
      finish_front(slot, finished_);
    }
  }
  if (slot.state == SlotState::kIdle && !slot.queue.empty()) start_attempt(slot);
}

RequestTracker::Attempt RequestTracker::begin_attempt(Slot& slot) {
  Pending& pending = slot.queue.front();
  ++pending.result.attempts;
  slot.state = SlotState::kSending;
  Attempt attempt;
  attempt.id = pending.id;
  attempt.payload = pending.payload;
  attempt.destination = pending.destination;
  attempt.serial = pending.serial;
  return attempt;
}

void RequestTracker::start_attempt(Slot& slot) {
  attempts_.push_back(begin_attempt(slot));
}

void RequestTracker::after_attempt(const Attempt& attempt, Clock::time_point now,
                                   std::vector<Finished>& finished) {
  Slot& slot = slots_[protocol::request_id_of(attempt.id)];
  // Already finished meanwhile (stop() failed everything during a caller's write).
  if (slot.queue.empty() || slot.queue.front().serial != attempt.serial) return;
  Pending& pending = slot.queue.front();
  if (!attempt.status) {
    if (slot.state == SlotState::kAcked) return;  // answered anyway; the ACK wins
    // An earlier attempt may have reached the wire; this one did not, and the link is down.
    pending.result.sent = pending.result.attempts > 1;
    pending.result.received = false;
    pending.result.code = protocol::ResponseCode::kFailure;
    pending.result.message = "could not send " + protocol::display_name(pending.id) + " (attempt " +
                             std::to_string(pending.result.attempts) +
                             "): " + attempt.status.message();
    finish_front(slot, finished);
    return;
  }
  if (pending.result.attempts == 1) ++counters_.requests;
  pending.result.sent = true;
  if (slot.state == SlotState::kSending) {
    slot.state = SlotState::kWaiting;
    // Sent once: as long as every attempt of a repeatable request would have waited.
    // (or as long as the action may take, for a pod that answers when done).
    slot.deadline = now + (pending.once ? once_wait(pending.id) : ack_timeout_);
  }
}

void RequestTracker::complete_with_ack(Slot& slot, std::vector<Finished>& finished) {
  Pending& pending = slot.queue.front();
  AckResult& result = pending.result;
  result.sent = true;
  result.received = true;
  result.payload.assign(slot.ack.bytes.begin(), slot.ack.bytes.begin() + slot.ack.size);
  result.code =
      protocol::ack_response_code(slot.ack.data(), slot.ack.size, ack_order_->codec_with(codec_));
  ++counters_.acks;
  if (slot.ack.size < 2) {
    ++counters_.nacks;
    result.message = "the ACK of " + protocol::display_name(pending.id) + " has " +
                     std::to_string(slot.ack.size) + " payload bytes, too few for a response code";
  } else if (result.code != protocol::ResponseCode::kOk) {
    ++counters_.nacks;
    const uint16_t code = static_cast<uint16_t>(result.code);
    result.message = protocol::display_name(pending.id) +
                     " refused by the pod: " + protocol::response_text(code) + " (response code " +
                     code_hex(code) + ")";
  } else {
    result.message = protocol::response_text(result.code);
  }
  finish_front(slot, finished);
}

void RequestTracker::finish_front(Slot& slot, std::vector<Finished>& finished) {
  Pending& pending = slot.queue.front();
  finished.push_back(Finished{std::move(pending.done), std::move(pending.result)});
  slot.queue.pop_front();
  slot.state = SlotState::kIdle;
}

void RequestTracker::fail_everything() {
  for (auto& entry : slots_) {
    Slot& slot = entry.second;
    while (!slot.queue.empty()) {
      Pending& pending = slot.queue.front();
      if (slot.state == SlotState::kAcked) {
        complete_with_ack(slot, finished_);  // the answer is here: deliver it
        continue;
      }
      pending.result.sent = pending.result.attempts > 0;
      pending.result.received = false;
      pending.result.code = protocol::ResponseCode::kFailure;
      pending.result.message =
          protocol::display_name(pending.id) + ": " + stop_reason_ +
          (pending.result.attempts > 0 ? " before its ACK came" : " before it was sent");
      finish_front(slot, finished_);
    }
  }
}

}  // namespace k40t::session
