// k40t probe's view of the link: a session that locks onto whatever checksum coverage the pod
// uses and keeps every frame the pod sends (raw payloads, source address, arrival time), so that
// the readings can be learned from the bytes themselves rather than from one decoding of them.
#pragma once

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "connection_waiter.h"
#include "k40t_driver/protocol/message_id.h"
#include "k40t_driver/protocol/result.h"
#include "k40t_driver/session/session.h"

namespace k40t::tool {

using ProbeClock = std::chrono::steady_clock;

struct HeardFrame {
  ProbeClock::time_point at;
  protocol::Address source;
  protocol::CrcCoverage coverage = protocol::CrcCoverage::kHeaderExcluded;
  std::vector<uint8_t> payload;
};

class ProbeLink {
 public:
  // Opens the URL (bad URL: the transport's message) and waits up to `connect_timeout` for the
  // link. Nothing is sent.
  static Result<std::unique_ptr<ProbeLink>> open(const std::string& url,
                                                 std::chrono::milliseconds connect_timeout,
                                                 std::chrono::milliseconds ack_timeout);
  ~ProbeLink();

  session::Session& session() { return *session_; }
  const std::string& url() const { return url_; }

  std::vector<HeardFrame> frames(protocol::MessageId id) const;
  std::vector<HeardFrame> frames_since(protocol::MessageId id, ProbeClock::time_point since) const;
  std::optional<HeardFrame> latest(protocol::MessageId id) const;
  size_t total_frames() const;
  std::vector<protocol::MessageId> ids() const;  // every id heard, in order
  // Good frames per checksum coverage they matched.
  std::map<protocol::CrcCoverage, size_t> coverage_counts() const;

  // Waits until `done()` holds (checked whenever a frame arrives) or the timeout passes.
  bool wait_until(const std::function<bool()>& done, std::chrono::milliseconds timeout);

 private:
  ProbeLink() = default;
  void keep(const protocol::FrameView& frame);

  std::string url_;
  ConnectionWaiter waiter_;  // before the session: its last state callback still reaches it
  mutable std::mutex mutex_;
  std::condition_variable arrived_;
  std::map<protocol::MessageId, std::vector<HeardFrame>> frames_;
  std::map<protocol::CrcCoverage, size_t> coverage_;
  size_t total_ = 0;
  std::unique_ptr<session::Session> session_;
};

}  // namespace k40t::tool
