// The pod link's state as a user reads it, from what the transport reports and what the pod
// sends. The transport alone cannot tell: a UDP socket is "connected" as soon as it exists, even
// with nothing at the other end, and it cannot tell a device that never opened from one that was
// lost, or a loss from the shutdown the user asked for.
//
//   starting    ->  cannot open   the device or socket could not be opened (retried)
//               ->  waiting       open, no valid frame yet ("waiting for the pod at <url>")
//   waiting     ->  connected     the first valid frame
//   waiting or connected -> no answer   no valid frame for link_timeout
//   connected or no answer -> lost      the transport lost an established link (reconnecting)
//   any         ->  stopped       stop() (a requested shutdown is never a loss)
//
// Not thread-safe: PodDriver calls it under its own lock.
#pragma once

#include <chrono>
#include <optional>
#include <string>

#include "k40t_driver/transport/transport.h"

namespace k40t::driver {

enum class PodLink { kStarting, kCannotOpen, kWaiting, kConnected, kNoAnswer, kLost, kStopped };
const char* to_string(PodLink state);

// A state and the sentence that tells it ("waiting for the pod at udp://10.0.0.2:2000").
struct PodLinkReport {
  PodLink state = PodLink::kStarting;
  std::string text;
};

class LinkMonitor {
 public:
  using Clock = std::chrono::steady_clock;

  LinkMonitor(std::string url, double link_timeout_s);

  // Each returns the new report when the state changed, for the caller to log.
  std::optional<PodLinkReport> on_transport(transport::LinkState state, const std::string& reason,
                                            Clock::time_point now);
  std::optional<PodLinkReport> on_frame(Clock::time_point now);
  // Call at deadline() (or later): turns waiting/connected into "no answer".
  std::optional<PodLinkReport> on_tick(Clock::time_point now);
  std::optional<PodLinkReport> on_stop();

  const PodLinkReport& report() const { return report_; }
  // When on_tick() may next change the state; nullopt: only an event can.
  std::optional<Clock::time_point> deadline() const;

 private:
  std::optional<PodLinkReport> enter(PodLink state, std::string text);
  std::string since_text(Clock::time_point now) const;

  const std::string url_;
  const Clock::duration timeout_;
  PodLinkReport report_;
  bool heard_ = false;              // a valid frame since the transport last connected
  Clock::time_point last_heard_{};  // the last frame, or when the transport connected
};

}  // namespace k40t::driver
