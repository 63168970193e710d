#include "k40t_driver/ros/pod_diagnostics.h"

#include <algorithm>
#include <cmath>

#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::driver {

namespace p = protocol;
using diagnostic_msgs::DiagnosticStatus;
using diagnostic_updater::DiagnosticStatusWrapper;

namespace {

const char* coverage_name(p::CrcCoverage coverage) {
  return coverage == p::CrcCoverage::kAuto ? "not locked yet" : p::to_string(coverage);
}

// Keeps the latest report of type Msg in `slot` (under `mutex`).
template <class Msg>
void keep_latest(PodDriver& driver, std::mutex& mutex, std::optional<Msg>& slot) {
  driver.on<Msg>([&mutex, &slot](const Msg& report, StampNs) {
    std::lock_guard<std::mutex> lock(mutex);
    slot = report;
  });
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
  updater_.add("link", this, &PodDiagnostics::link);
  // The document's rates (docs/protocol/decisions.md#periodic-reports).
  add_rate_check<p::GimbalStatus>(driver, "gimbal status report (0x000001)", 2.0);
  add_rate_check<p::GimbalAttitude>(driver, "gimbal attitude report (0x000002)", 10.0);
  add_rate_check<p::CameraSystemStatus>(driver, "camera status report (0x000003)", 1.0);
  add_rate_check<p::ThermalStatus>(driver, "thermal report (0x000004)", 5.0);
  add_rate_check<p::VisibleStatus>(driver, "visible report (0x000005)", 5.0);
  updater_.add("self-test", this, &PodDiagnostics::self_test);
  updater_.add("stabilisation", this, &PodDiagnostics::stabilisation);
  updater_.add("SD card", this, &PodDiagnostics::sd_card);
  updater_.add("temperature alarms", this, &PodDiagnostics::alarms);
  if (settings_) updater_.add("settings", this, &PodDiagnostics::settings);

  keep_latest(driver, mutex_, gimbal_);
  keep_latest(driver, mutex_, camera_);
  keep_latest(driver, mutex_, thermal_);

  timer_ = nh.createSteadyTimer(ros::WallDuration(period_s_),
                                [this](const ros::SteadyTimerEvent&) { update(); });
}

template <class Msg>
void PodDiagnostics::add_rate_check(PodDriver& driver, const std::string& name, double rate_hz) {
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
  updater_.add(*status);
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

void PodDiagnostics::link(DiagnosticStatusWrapper& stat) {
  const DriverStats s = driver_.stats();
  const transport::LinkState state = s.session.link_state;
  const double silent = s.seconds_since_last_frame;
  if (driver_.replay()) {
    stat.summary(DiagnosticStatus::OK, silent < 0 ? "replay: no frame yet" : "replay");
  } else if (state != transport::LinkState::kConnected) {
    stat.summaryf(
        DiagnosticStatus::ERROR, "link %s: %s", transport::to_string(state),
        s.session.link.last_error.empty() ? "not connected" : s.session.link.last_error.c_str());
  } else if (silent < 0) {
    stat.summary(DiagnosticStatus::ERROR, "connected, but the pod has sent nothing");
  } else if (silent > driver_.options().silence_timeout_s) {
    stat.summaryf(DiagnosticStatus::ERROR, "pod silent for %.1f s", silent);
  } else {
    stat.summary(DiagnosticStatus::OK, "receiving");
  }
  const p::ParserStats& parser = s.session.parser;
  stat.add("device", driver_.replay() ? std::string("replay of raw/rx") : driver_.options().device);
  stat.add("state", transport::to_string(state));
  stat.add("last error", s.session.link.last_error);
  stat.add("seconds since last frame", silent);
  stat.add("crc coverage", coverage_name(s.crc_coverage));
  stat.add("bytes received", parser.bytes_received);
  stat.add("bytes sent", s.session.link.bytes_sent);
  stat.add("frames received", parser.frames_good);
  stat.add("frames sent", s.session.frames_sent);
  stat.add("checksum errors", parser.checksum_errors);
  stat.add("length errors", parser.length_errors);
  stat.add("bytes discarded", parser.bytes_discarded);
  stat.add("unknown ids", parser.unknown_ids);
  stat.add("sequence gaps", parser.sequence_gaps);
  stat.add("frames lost", parser.frames_lost);
  stat.add("frames repeated", parser.frames_repeated);
  stat.add("decode errors", s.session.decode_errors);
  stat.add("requests", s.session.requests);
  stat.add("acks", s.session.acks);
  stat.add("nacks", s.session.nacks);
  stat.add("ack timeouts", s.session.ack_timeouts);
  stat.add("retries", s.session.retries);
  stat.add("late acks", s.session.late_acks);
  stat.add("connects", s.session.link.connects);
  stat.add("disconnects", s.session.link.disconnects);
  stat.add("pod online events", s.pod_online_events);
  stat.add("time syncs sent", s.time_syncs_sent);
  stat.add("gps requests answered", s.gps_requests_answered);
  stat.add("gps requests without fix", s.gps_requests_unanswerable);
  stat.add("gps requests time-matched", s.gps_requests_time_matched);
  stat.add("gps requests outside the history", s.gps_requests_out_of_history);
  stat.add("last geotag gap to a fix (s)", s.last_geotag_gap_s);
  stat.add("cmd_rate dead-man stops", s.deadman_stops);
}

void PodDiagnostics::self_test(DiagnosticStatusWrapper& stat) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!gimbal_) return stat.summary(DiagnosticStatus::WARN, "no gimbal status report yet");
  const p::GimbalStatus& g = *gimbal_;
  std::string failed;
  auto sensor = [&](const char* name, bool ok) {
    stat.add(name, ok ? "passed" : "FAILED");
    if (!ok) failed += failed.empty() ? name : std::string(", ") + name;
  };
  sensor("thermal", g.ir_ok);
  sensor("tele", g.tele_ok);
  sensor("wide", g.wide_ok);
  sensor("laser", g.laser_ok);
  const bool links_ok =
      g.gimbal_link == p::GimbalLinkState::kNormal && g.camera_link == p::GimbalLinkState::kNormal;
  stat.add("gimbal link", p::to_string(g.gimbal_link) ? p::to_string(g.gimbal_link) : "unknown");
  stat.add("camera link", p::to_string(g.camera_link) ? p::to_string(g.camera_link) : "unknown");
  stat.add("upgrade", p::to_string(g.upgrade) ? p::to_string(g.upgrade) : "unknown");
  if (!failed.empty()) {
    stat.summaryf(DiagnosticStatus::ERROR, "self-test failed: %s", failed.c_str());
  } else if (!links_ok) {
    stat.summary(DiagnosticStatus::ERROR, "gimbal or camera connection abnormal");
  } else if (g.upgrade != p::GimbalUpgradeState::kNormal) {
    stat.summary(DiagnosticStatus::WARN, "firmware upgrade not completed");
  } else {
    stat.summary(DiagnosticStatus::OK, "all sensors passed");
  }
}

void PodDiagnostics::stabilisation(DiagnosticStatusWrapper& stat) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!gimbal_) return stat.summary(DiagnosticStatus::WARN, "no gimbal status report yet");
  const char* text = p::to_string(gimbal_->stabilisation);
  const bool trouble = gimbal_->stabilisation == p::GimbalStabilisationState::kFailed ||
                       gimbal_->stabilisation == p::GimbalStabilisationState::kFeatureLost;
  stat.summary(trouble ? DiagnosticStatus::WARN : DiagnosticStatus::OK,
               text ? text : "unknown state");
  stat.add("state code", static_cast<int>(gimbal_->stabilisation));
}

void PodDiagnostics::sd_card(DiagnosticStatusWrapper& stat) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!camera_) return stat.summary(DiagnosticStatus::WARN, "no camera status report yet");
  const p::CameraSystemStatus& c = *camera_;
  const char* text = p::to_string(c.sd_state);
  uint8_t level = DiagnosticStatus::OK;
  switch (c.sd_state) {
    case p::SdCardState::kNormal:
      break;
    case p::SdCardState::kAbnormal:
    case p::SdCardState::kFormatError:
      level = DiagnosticStatus::ERROR;
      break;
    default:
      level = DiagnosticStatus::WARN;
      break;  // slow, missing, full, undocumented
  }
  stat.summary(level, text ? text : "unknown SD card state");
  stat.add("total MB", c.sd_total_mb);
  stat.add("free MB", c.sd_free_mb);
  stat.add("used MB", c.sd_used_mb);
}

void PodDiagnostics::alarms(DiagnosticStatusWrapper& stat) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!thermal_) return stat.summary(DiagnosticStatus::WARN, "no thermal report yet");
  const p::ThermalStatus& t = *thermal_;
  std::string active;
  auto alarm = [&](const char* name, bool on) {
    stat.add(name, on);
    if (on) active += active.empty() ? name : std::string(", ") + name;
  };
  alarm("high temperature", t.high_alarm);
  alarm("low temperature", t.low_alarm);
  alarm("temperature difference", t.difference_alarm);
  alarm("threshold", t.threshold_alarm);
  stat.add("max degC", t.max_degC);
  stat.add("min degC", t.min_degC);
  if (active.empty()) {
    stat.summary(DiagnosticStatus::OK, "no alarm");
  } else {
    stat.summaryf(DiagnosticStatus::WARN, "alarm: %s", active.c_str());
  }
}

void PodDiagnostics::settings(DiagnosticStatusWrapper& stat) {
  const SettingsState s = settings_->state();
  if (s.reads == 0) {
    stat.summary(DiagnosticStatus::WARN, "settings not read from the pod yet");
  } else if (!s.read_ok) {
    stat.summaryf(DiagnosticStatus::WARN, "settings read-back incomplete: %s",
                  s.read_message.c_str());
  } else if (!s.last_refusal.empty()) {
    stat.summaryf(DiagnosticStatus::WARN, "last change refused and reverted: %s",
                  s.last_refusal.c_str());
  } else {
    stat.summary(DiagnosticStatus::OK, "in sync with the pod");
  }
  stat.add("read-backs", s.reads);
  stat.add("last read-back", s.read_message);
  stat.add("changes applied", s.changes_applied);
  stat.add("changes refused", s.changes_refused);
  stat.add("last refusal", s.last_refusal);
}

}  // namespace k40t::driver
