#include "k40t_driver/sim/faulty_transport.h"

#include <utility>

namespace k40t::sim {

namespace {
void accumulate(transport::LinkStats& into, const transport::LinkStats& from) {
  into.bytes_sent += from.bytes_sent;
  into.bytes_received += from.bytes_received;
  into.writes += from.writes;
  into.reads += from.reads;
  into.send_errors += from.send_errors;
  into.connects += from.connects;
  into.disconnects += from.disconnects;
  if (!from.last_error.empty()) into.last_error = from.last_error;
}
}  // namespace

FaultyTransport::FaultyTransport(Factory factory, std::string url, FaultInjector& faults,
                                 CaptureWriter* capture)
    : factory_(std::move(factory)), url_(std::move(url)), faults_(faults), capture_(capture) {}

FaultyTransport::~FaultyTransport() {
  close();
}

void FaultyTransport::report(transport::LinkState state, const std::string& reason) {
  if (on_state_) on_state_(state, reason);
}

Status FaultyTransport::open_inner() {
  Result<std::unique_ptr<transport::Transport>> made = factory_();
  if (!made) return made.status();
  std::unique_ptr<transport::Transport> inner = std::move(made).value();
  inner->set_receive_callback([this](const uint8_t* data, size_t size) {
    if (capture_) capture_->received(data, size);
    if (on_receive_) on_receive_(data, size);
  });
  inner->set_state_callback(
      [this](transport::LinkState state, const std::string& reason) { report(state, reason); });
  inner->set_reconnect_policy(policy_);
  const Status opened = inner->open();
  if (!opened) return opened;
  std::lock_guard<std::mutex> lock(mutex_);
  inner_ = std::move(inner);
  return Status::ok();
}

Status FaultyTransport::open() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (opened_) return Status::ok();
    opened_ = true;
  }
  return open_inner();
}

void FaultyTransport::close() {
  std::unique_ptr<transport::Transport> inner;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    opened_ = false;
    disconnected_ = false;
    inner = std::move(inner_);
    if (inner) accumulate(retired_, inner->stats());
  }
  // Closed outside the lock: the link's I/O thread may be inside a callback that sends.
  if (inner) inner->close();
}

Status FaultyTransport::send(const uint8_t* data, size_t size) {
  const std::vector<uint8_t> wire = faults_.outgoing(data, size);
  if (wire.empty()) return Status::ok();  // silenced: the bytes are swallowed, not an error
  std::lock_guard<std::mutex> lock(mutex_);
  if (!inner_) return Status::fail(url_ + ": disconnected (fault injection)");
  const Status sent = inner_->send(wire.data(), wire.size());
  if (sent && capture_) capture_->sent(wire.data(), wire.size());
  return sent;
}

transport::LinkState FaultyTransport::state() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (disconnected_) return transport::LinkState::kReconnecting;
  return inner_ ? inner_->state() : transport::LinkState::kClosed;
}

transport::LinkStats FaultyTransport::stats() const {
  std::lock_guard<std::mutex> lock(mutex_);
  transport::LinkStats total = retired_;
  if (inner_) accumulate(total, inner_->stats());
  return total;
}

double FaultyTransport::seconds_per_byte() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return inner_ ? inner_->seconds_per_byte() : 0.0;
}

void FaultyTransport::disconnect_for(std::chrono::milliseconds duration,
                                     SteadyClock::time_point now) {
  std::unique_ptr<transport::Transport> inner;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!opened_) return;
    reopen_at_ = now + duration;
    if (disconnected_) return;  // already down: just extend
    disconnected_ = true;
    inner = std::move(inner_);
    if (inner) accumulate(retired_, inner->stats());
  }
  faults_.count_disconnect();
  if (inner) inner->close();
  report(transport::LinkState::kReconnecting, url_ + ": disconnected by fault injection for " +
                                                  std::to_string(duration.count()) + " ms");
}

void FaultyTransport::poll(SteadyClock::time_point now) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!disconnected_ || now < reopen_at_) return;
    disconnected_ = false;
  }
  const Status reopened = open_inner();
  if (!reopened) {
    std::lock_guard<std::mutex> lock(mutex_);
    disconnected_ = true;  // try again at the next poll
    reopen_at_ = now + std::chrono::milliseconds(500);
    retired_.last_error = reopened.message();
  }
}

bool FaultyTransport::disconnected() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return disconnected_;
}

}  // namespace k40t::sim
