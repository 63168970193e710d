#include "probe_link.h"

namespace k40t::tool {

Result<std::unique_ptr<ProbeLink>> ProbeLink::open(const std::string& url,
                                                   std::chrono::milliseconds connect_timeout,
                                                   std::chrono::milliseconds ack_timeout) {
  using Opened = Result<std::unique_ptr<ProbeLink>>;
  Result<std::unique_ptr<transport::Transport>> transport = transport::make_transport(url);
  if (!transport) return Opened::fail(transport.error());
  std::unique_ptr<ProbeLink> link(new ProbeLink());
  link->url_ = url;
  session::SessionOptions options;
  // docs/protocol/decisions.md#a1: auto accepts both coverages; each frame says which it matched.
  options.crc_coverage = protocol::CrcCoverage::kAuto;
  options.ack_timeout = ack_timeout;
  options.retries = 1;
  link->session_ = std::make_unique<session::Session>(std::move(transport).value(), options);
  ProbeLink* self = link.get();
  link->session_->dispatcher().on_frame([self](const protocol::FrameView& f) { self->keep(f); });
  link->session_->on_link_state([self](transport::LinkState state, const std::string& reason) {
    self->waiter_.update(state, reason);
  });
  const Status started = link->session_->start();
  if (!started) return Opened::fail(started.message());
  if (!link->waiter_.wait(connect_timeout, *link->session_)) {
    const std::string reason = link->waiter_.last_reason();
    return Opened::fail(url + ": not connected after " + std::to_string(connect_timeout.count()) +
                        " ms" + (reason.empty() ? "" : ": " + reason));
  }
  return Opened(std::move(link));
}

ProbeLink::~ProbeLink() {
  if (session_) session_->stop();
}

void ProbeLink::keep(const protocol::FrameView& frame) {
  HeardFrame heard;
  heard.at = ProbeClock::now();
  heard.source = frame.header.source;
  heard.coverage = frame.coverage;
  heard.payload.assign(frame.payload, frame.payload + frame.payload_size);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    frames_[frame.header.message_id].push_back(std::move(heard));
    ++coverage_[frame.coverage];
    ++total_;
  }
  arrived_.notify_all();
}

std::vector<HeardFrame> ProbeLink::frames(protocol::MessageId id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto found = frames_.find(id);
  return found == frames_.end() ? std::vector<HeardFrame>{} : found->second;
}

std::vector<HeardFrame> ProbeLink::frames_since(protocol::MessageId id,
                                                ProbeClock::time_point since) const {
  std::vector<HeardFrame> all = frames(id);
  std::vector<HeardFrame> after;
  for (HeardFrame& f : all) {
    if (f.at >= since) after.push_back(std::move(f));
  }
  return after;
}

std::optional<HeardFrame> ProbeLink::latest(protocol::MessageId id) const {
  std::lock_guard<std::mutex> lock(mutex_);
  const auto found = frames_.find(id);
  if (found == frames_.end() || found->second.empty()) return std::nullopt;
  return found->second.back();
}

size_t ProbeLink::total_frames() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return total_;
}

std::vector<protocol::MessageId> ProbeLink::ids() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<protocol::MessageId> heard;
  for (const auto& entry : frames_) heard.push_back(entry.first);
  return heard;
}

std::map<protocol::CrcCoverage, size_t> ProbeLink::coverage_counts() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return coverage_;
}

bool ProbeLink::wait_until(const std::function<bool()>& done, std::chrono::milliseconds timeout) {
  const auto deadline = ProbeClock::now() + timeout;
  while (true) {
    size_t seen = 0;
    {
      std::lock_guard<std::mutex> lock(mutex_);
      seen = total_;
    }
    if (done()) return true;
    // Re-check after every frame; the count taken before done() means no frame is missed.
    std::unique_lock<std::mutex> lock(mutex_);
    if (!arrived_.wait_until(lock, deadline, [&] { return total_ != seen; })) {
      lock.unlock();
      return done();
    }
  }
}

}  // namespace k40t::tool
