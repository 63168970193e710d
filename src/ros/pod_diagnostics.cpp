#include "k40t_driver/ros/pod_diagnostics.h"

#include <algorithm>
#include <cmath>
#include <variant>

#include "k40t_driver/driver/convention_health.h"
#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::driver {

namespace p = protocol;
using diagnostic_updater::DiagnosticStatusWrapper;

namespace {

// Keeps the latest report of type Msg in `slot` (under `mutex`).
template <class Msg>
void keep_latest(PodDriver& driver, std::mutex& mutex, std::optional<Msg>& slot) {
  driver.on<Msg>([&mutex, &slot](const Msg& report, StampNs) {
    std::lock_guard<std::mutex> lock(mutex);
    slot = report;
  });
}

// A ROS-free check as diagnostic_updater shows it: each value formatted as its type is.
void fill(DiagnosticStatusWrapper& stat, const HealthCheck& check) {
  stat.summary(static_cast<uint8_t>(check.level), check.summary);
  for (const auto& [key, value] : check.values) {
    std::visit([&stat, &key = key](const auto& v) { stat.add(key, v); }, value);
  }
}

}  // namespace

PodDiagnostics::PodDiagnostics(ros::NodeHandle nh, ros::NodeHandle private_nh, PodDriver& driver,
                               const RosPodConfig& config, const SettingsSync* settings)
    : driver_(driver),
      config_(config),
      settings_(settings),
      updater_(nh, private_nh, private_nh.getNamespace()),
      period_s_(private_nh.param("diagnostic_period", 0.25)) {
  updater_.setHardwareID(hardware_id_);
  add_check("link", [this] {
    LinkContext context;
    context.replay = driver_.replay();
    context.device = driver_.options().device;
    context.silence_timeout_s = driver_.options().silence_timeout_s;
    context.link = driver_.link_report();
    return link_health(driver_.stats(), context);
  });
  // The document's rates (docs/protocol/decisions.md#periodic-reports).
  add_rate_check<p::GimbalStatus>(driver, "gimbal status report (0x000001)", 2.0);
  add_rate_check<p::GimbalAttitude>(driver, "gimbal attitude report (0x000002)", 10.0);
  add_rate_check<p::CameraSystemStatus>(driver, "camera status report (0x000003)", 1.0);
  // Only while the pod measures temperatures (section 3.2.2.4); off, no report is the right rate.
  add_rate_check<p::ThermalStatus>(driver, "thermal report (0x000004)", 5.0, [this] {
    return measurement_.measuring() ? std::string()
                                    : std::string("temperature measurement off: none expected");
  });
  add_rate_check<p::VisibleStatus>(driver, "visible report (0x000005)", 5.0);
  add_report_check("self-test", gimbal_, self_test_health);
  add_report_check("stabilisation", gimbal_, stabilisation_health);
  add_report_check("SD card", camera_, sd_card_health);
  add_check("temperature alarms", [this] {
    std::lock_guard<std::mutex> lock(mutex_);
    ThermalContext context;
    context.measuring = measurement_.measuring();
    context.report_age_s = std::chrono::duration<double>(SteadyClock::now() - thermal_at_).count();
    return alarms_health(thermal_, context);
  });
  if (settings_) add_check("settings", [this] { return settings_health(settings_->state()); });
  add_check("conventions", [this] { return conventions_health(driver_.conventions_report()); });

  keep_latest(driver, mutex_, gimbal_);
  keep_latest(driver, mutex_, camera_);
  driver.on<p::ThermalStatus>([this](const p::ThermalStatus& report, StampNs) {
    std::lock_guard<std::mutex> lock(mutex_);
    thermal_ = report;
    thermal_at_ = SteadyClock::now();
  });
  driver.on_tx_frame([this](const p::FrameView& frame, StampNs) {
    measurement_.frame_sent(frame, driver_.codec());
  });
  driver.on_rx_frame([this](const p::FrameView& frame, StampNs) {
    measurement_.frame_received(frame, driver_.codec());
  });

  timer_ = nh.createSteadyTimer(ros::WallDuration(period_s_),
                                [this](const ros::SteadyTimerEvent&) { update(); });
}

template <class Msg>
void PodDiagnostics::add_rate_check(PodDriver& driver, const std::string& name, double rate_hz,
                                    std::function<std::string()> not_expected) {
  auto check = std::make_unique<RateCheck>();
  check->min_hz = rate_hz * (1.0 - config_.rate_tolerance);
  check->max_hz = rate_hz * (1.0 + config_.rate_tolerance);
  // The window holds ~2.5 report periods (so jitter does not read as a wrong rate) and at least
  // two updates; silence turns it to "No events recorded" (ERROR) after one window.
  const int window = std::max(2, static_cast<int>(std::ceil(2.5 / (rate_hz * period_s_))));
  check->status = std::make_unique<diagnostic_updater::FrequencyStatus>(
      diagnostic_updater::FrequencyStatusParam(&check->min_hz, &check->max_hz, 0.0, window), name);
  diagnostic_updater::FrequencyStatus* status = check->status.get();
  driver.on<Msg>([status](const Msg&, StampNs) { status->tick(); });
  if (!not_expected) {
    updater_.add(*status);
  } else {
    // The window slides on as usual (no stale counts when the reports resume); while the reason
    // holds, silence is what the pod should do.
    updater_.add(name, [status, not_expected](DiagnosticStatusWrapper& stat) {
      status->run(stat);
      const std::string reason = not_expected();
      if (!reason.empty()) stat.summary(diagnostic_msgs::DiagnosticStatus::OK, reason);
    });
  }
  rates_.push_back(std::move(check));
}

void PodDiagnostics::set_versions(const PodVersions& versions) {
  std::lock_guard<std::mutex> lock(mutex_);
  hardware_id_ = versions.hardware_id();
}

void PodDiagnostics::update() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    updater_.setHardwareID(hardware_id_);
  }
  updater_.force_update();
}

template <class Msg>
void PodDiagnostics::add_report_check(const std::string& name, const std::optional<Msg>& latest,
                                      HealthCheck (*check)(const std::optional<Msg>&)) {
  add_check(name, [this, &latest, check] {
    std::lock_guard<std::mutex> lock(mutex_);
    return check(latest);
  });
}

void PodDiagnostics::add_check(const std::string& name, std::function<HealthCheck()> check) {
  updater_.add(name,
               [check = std::move(check)](DiagnosticStatusWrapper& stat) { fill(stat, check()); });
}

}  // namespace k40t::driver
