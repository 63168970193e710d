// PodDriver's link state (link_monitor.h): what the transport reports and the shutdown that
// may explain a loss. The frames' side is handle_rx_frame() and timer_loop() in pod_driver.cpp.
#include <thread>

#include "k40t_driver/driver/pod_driver.h"

namespace k40t::driver {

namespace {

// How long a loss waits for the shutdown that may explain it (shutdown_explains_loss()). Costs a
// real loss nothing but this delay of its report; the link is retried after it as before.
constexpr std::chrono::milliseconds kShutdownGrace{250};

}  // namespace

void PodDriver::on_link_report(LinkReportHandler handler) {
  link_report_handlers_.push_back(std::move(handler));
}
void PodDriver::set_shutdown_query(std::function<bool()> shutting_down) {
  shutting_down_ = std::move(shutting_down);
}

void PodDriver::handle_link_state(transport::LinkState state, const std::string& reason) {
  const bool shutting_down =
      state == transport::LinkState::kReconnecting && shutdown_explains_loss();
  std::optional<PodLinkReport> report;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (state == transport::LinkState::kConnected) reconnected_since_frame_ = true;
    rate_.forget_speed();  // a pod (re)connected may be another, or restarted
    report = shutting_down ? link_monitor_.on_stop()
                           : link_monitor_.on_transport(state, reason, SteadyClock::now());
  }
  wake_.notify_all();  // a new "no answer" deadline
  deliver(report);
  for (const LinkStateHandler& handler : link_handlers_) handler(state, reason);
}

bool PodDriver::shutdown_explains_loss() {
  if (!shutting_down_) return false;
  {
    std::lock_guard<std::mutex> lock(mutex_);
    const PodLink now = link_monitor_.report().state;
    if (now != PodLink::kWaiting && now != PodLink::kConnected && now != PodLink::kNoAnswer)
      return false;  // no open link: a failed attempt, no loss to explain
  }
  // A Ctrl-C reaches every process of the terminal at once, and the simulator may close the link
  // before this process has even run its signal handler (on a busy machine the thread the kernel
  // picked for the signal runs later): give it a moment before calling this a loss. Asked outside
  // our lock: the query may take the glue's locks.
  const auto until = SteadyClock::now() + kShutdownGrace;
  while (!shutting_down_()) {
    if (SteadyClock::now() >= until) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return true;
}

void PodDriver::deliver(const std::optional<PodLinkReport>& report) {
  if (!report) return;
  for (const LinkReportHandler& handler : link_report_handlers_) handler(*report);
}

PodLinkReport PodDriver::link_report() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return link_monitor_.report();
}

}  // namespace k40t::driver
