#include "k40t_driver/driver/link_monitor.h"

#include <cstdio>
#include <utility>

#include "k40t_driver/codec/enum_names.h"

namespace k40t::driver {
namespace {

// The transport's reason without what the sentence around it already says: its "<url>: "
// prefix and a leading "cannot open <path>: ".
std::string bare_reason(const std::string& url, std::string reason) {
  const std::string prefix = url + ": ";
  if (reason.compare(0, prefix.size(), prefix) == 0) reason.erase(0, prefix.size());
  const std::string cannot_open = "cannot open ";
  if (reason.compare(0, cannot_open.size(), cannot_open) == 0) {
    const size_t colon = reason.find(": ");
    if (colon != std::string::npos) reason.erase(0, colon + 2);
  }
  return reason;
}

}  // namespace

const char* to_string(PodLink state) {
  static constexpr EnumName<PodLink> kNames[] = {
      {PodLink::kStarting, "starting"},  {PodLink::kCannotOpen, "cannot open"},
      {PodLink::kWaiting, "waiting"},    {PodLink::kConnected, "connected"},
      {PodLink::kNoAnswer, "no answer"}, {PodLink::kLost, "lost"},
      {PodLink::kStopped, "stopped"}};
  return name_in(kNames, state, "invalid pod link state");
}

LinkMonitor::LinkMonitor(std::string url, double link_timeout_s)
    : url_(std::move(url)),
      timeout_(std::chrono::duration_cast<Clock::duration>(
          std::chrono::duration<double>(link_timeout_s))) {
  report_.text = "starting the link to the pod at " + url_;
}

std::optional<PodLinkReport> LinkMonitor::enter(PodLink state, std::string text) {
  if (report_.state == PodLink::kStopped) return std::nullopt;  // nothing after a shutdown
  if (state == report_.state && text == report_.text) return std::nullopt;
  report_ = PodLinkReport{state, std::move(text)};
  return report_;
}

std::optional<PodLinkReport> LinkMonitor::on_transport(transport::LinkState state,
                                                       const std::string& reason,
                                                       Clock::time_point now) {
  switch (state) {
    case transport::LinkState::kConnected:
      heard_ = false;
      last_heard_ = now;
      return enter(PodLink::kWaiting, "waiting for the pod at " + url_);
    case transport::LinkState::kReconnecting: {
      const bool was_open = report_.state == PodLink::kWaiting ||
                            report_.state == PodLink::kConnected ||
                            report_.state == PodLink::kNoAnswer;
      if (was_open) {
        return enter(PodLink::kLost, "link to the pod at " + url_ +
                                         " lost: " + bare_reason(url_, reason) + "; reconnecting");
      }
      return enter(PodLink::kCannotOpen,
                   "cannot open " + url_ + ": " + bare_reason(url_, reason) + " (retrying)");
    }
    case transport::LinkState::kClosed:
      return on_stop();
    case transport::LinkState::kConnecting:
      break;
  }
  return std::nullopt;
}

std::optional<PodLinkReport> LinkMonitor::on_frame(Clock::time_point now) {
  heard_ = true;
  last_heard_ = now;
  if (report_.state == PodLink::kConnected) return std::nullopt;
  return enter(PodLink::kConnected, "connected to the pod at " + url_);
}

std::string LinkMonitor::since_text(Clock::time_point now) const {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s",
                std::chrono::duration<double>(now - last_heard_).count());
  return text;
}

std::optional<PodLinkReport> LinkMonitor::on_tick(Clock::time_point now) {
  const std::optional<Clock::time_point> due = deadline();
  if (!due || now < *due) return std::nullopt;
  if (!heard_) {
    return enter(PodLink::kNoAnswer, "waiting for the pod at " + url_ +
                                         ": nothing has answered for " + since_text(now));
  }
  return enter(PodLink::kNoAnswer, "no answer from the pod at " + url_ + " for " + since_text(now));
}

std::optional<PodLinkReport> LinkMonitor::on_stop() {
  return enter(PodLink::kStopped, "link to the pod at " + url_ + " closed");
}

std::optional<LinkMonitor::Clock::time_point> LinkMonitor::deadline() const {
  if (report_.state != PodLink::kWaiting && report_.state != PodLink::kConnected)
    return std::nullopt;
  return last_heard_ + timeout_;
}

}  // namespace k40t::driver
