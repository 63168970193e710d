#include "k40t_driver/driver/convention_tracker.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <utility>

#include "k40t_driver/protocol/ack_byte_order_evidence.h"

namespace k40t::driver {

namespace p = protocol;

namespace {

// A checked move: the report must have moved this far (deg) before its direction counts.
constexpr double kMoveDeg = 2.0;
// An angle command counts once the gimbal has stopped (deg/s) this close (deg) to +-target, and
// no sooner than this after the command (a gimbal still at -target has not started yet).
constexpr double kSettledDegS = 1.0;
constexpr double kNearDeg = 1.0;
constexpr double kSettleS = 1.0;
// A command whose move does not show within this long teaches nothing.
constexpr double kCheckWindowS = 10.0;

std::string degrees(double deg) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f deg", deg);
  return text;
}

std::string hex_byte(unsigned byte) {
  char text[8];
  std::snprintf(text, sizeof text, "0x%02X", byte & 0xFFu);
  return text;
}

}  // namespace

ConventionTracker::ConventionTracker(p::CrcCoverage crc_coverage, const p::CodecOptions& codec,
                                     std::set<std::string> from_parameters)
    : crc_coverage_(crc_coverage), codec_(codec), from_parameters_(std::move(from_parameters)) {}

double ConventionTracker::steady_now_s() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

p::Conventions ConventionTracker::conventions() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return codec_.conventions;
}

p::YawRange ConventionTracker::yaw_range() const {
  std::lock_guard<std::mutex> lock(mutex_);
  const p::YawRange range = codec_.conventions.yaw_range;
  return range == p::YawRange::kAuto ? p::YawRange::kSigned : range;
}

void ConventionTracker::detect(const std::string& name, std::string evidence) {
  for (const auto& d : detected_)
    if (d.first == name) return;
  detected_.emplace_back(name, "detected from " + evidence);
}

void ConventionTracker::contradict(const std::string& name, std::string why) {
  for (const auto& c : contradictions_)
    if (c.first == name) return;  // the first one says it; the diagnostic stays WARN
  contradictions_.emplace_back(name, std::move(why));
}

void ConventionTracker::observe_attitude(const p::GimbalAttitude& as_decoded, double now_s) {
  std::lock_guard<std::mutex> lock(mutex_);
  const p::YawRange seen = p::yaw_range_evidence(as_decoded);
  p::YawRange& range = codec_.conventions.yaw_range;
  const bool was_auto = range == p::YawRange::kAuto;  // once locked, later reports check it
  // Written only when it is kept: this runs for every attitude report (10 Hz).
  const auto evidence = [&as_decoded] {
    return "0x000002 yaw " + degrees(as_decoded.yaw_deg) + ", joint yaw " +
           degrees(as_decoded.joint_yaw_deg) + " read as int16";
  };
  if (seen != p::YawRange::kAuto) {
    if (was_auto) {
      range = seen;
      detect("yaw_range", evidence());
    } else if (seen != range) {
      contradict("yaw_range", evidence() + " fits only yaw_range: " +
                                  (seen == p::YawRange::kHeading ? "heading" : "signed"));
    }
  }
  p::GimbalAttitude now = as_decoded;
  p::attitude_from_wire(now, codec_.conventions,
                        range == p::YawRange::kHeading ? range : p::YawRange::kSigned);
  last_attitude_ = now;
  check_calibration(now_s);
  finish_check(yaw_check_, "yaw", now.joint_yaw_deg, now.yaw_rate_deg_s, now_s);
  finish_check(pitch_check_, "pitch", now.joint_pitch_deg, now.pitch_rate_deg_s, now_s);
}

void ConventionTracker::start_check(AxisCheck& check, bool by_angle, double expected,
                                    double baseline, double now_s, std::string text) {
  check.pending = true;
  check.by_angle = by_angle;
  check.expected = expected;
  check.baseline = baseline;
  check.since_s = now_s;
  check.command_text = std::move(text);
}

void ConventionTracker::observe_command(const p::GimbalControlRequest& command, double now_s) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!last_attitude_) return;  // nothing to measure the move from
  if (command.yaw != p::GimbalYawDirection::kStop) {
    const bool right = command.yaw == p::GimbalYawDirection::kRight;
    start_check(yaw_check_, false, right ? 1 : -1, last_attitude_->joint_yaw_deg, now_s,
                std::string("0x000010 yaw ") + (right ? "right" : "left"));
  }
  if (command.pitch != p::GimbalPitchDirection::kStop) {
    const bool up = command.pitch == p::GimbalPitchDirection::kUp;
    start_check(pitch_check_, false, up ? 1 : -1, last_attitude_->joint_pitch_deg, now_s,
                std::string("0x000010 pitch ") + (up ? "up" : "down"));
  }
}

void ConventionTracker::observe_command(const p::GimbalAngleRequest& command, double now_s) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!last_attitude_) return;
  // A target this close to 0 reads the same in both signs.
  if (command.yaw_move && std::abs(command.yaw_deg) >= kMoveDeg) {
    start_check(yaw_check_, true, command.yaw_deg, last_attitude_->joint_yaw_deg, now_s,
                "0x000012 yaw " + degrees(std::abs(command.yaw_deg)) +
                    (command.yaw_deg > 0 ? " right" : " left"));
  }
  if (command.pitch_move && std::abs(command.pitch_deg) >= kMoveDeg) {
    start_check(pitch_check_, true, command.pitch_deg, last_attitude_->joint_pitch_deg, now_s,
                "0x000012 pitch " + degrees(std::abs(command.pitch_deg)) +
                    (command.pitch_deg > 0 ? " up" : " down"));
  }
}

void ConventionTracker::finish_check(AxisCheck& check, const char* axis, double angle, double rate,
                                     double now_s) {
  if (!check.pending) return;
  if (now_s - check.since_s > kCheckWindowS) {
    check.pending = false;
    return;
  }
  bool agrees = false;
  bool disagrees = false;
  if (check.by_angle) {
    if (now_s - check.since_s < kSettleS || std::abs(rate) > kSettledDegS) return;
    agrees = std::abs(angle - check.expected) < kNearDeg;
    disagrees = std::abs(angle + check.expected) < kNearDeg;
  } else {
    const double moved = angle - check.baseline;
    if (std::abs(moved) < kMoveDeg) return;
    agrees = (moved > 0) == (check.expected > 0);
    disagrees = !agrees;
  }
  if (!agrees && !disagrees) return;
  check.pending = false;
  if (agrees) return;
  const bool yaw = std::string(axis) == "yaw";
  const std::string name = yaw ? "yaw_sign" : "pitch_sign";
  const p::ConventionInfo* info = p::find_convention(name);
  const std::string value = info->get(*info, {crc_coverage_, codec_});
  const std::string other = info->values[0] == value ? info->values[1] : info->values[0];
  contradict(name, check.command_text + " but 0x000002 counts the " + axis + " as " +
                       degrees(angle) + " (from " + degrees(check.baseline) + ") under " + name +
                       ": " + value + "; the pod's " + axis + " is " + other + "-positive (" +
                       name + ": " + other + ")");
}

void ConventionTracker::observe_thermal_settings(const p::ThermalSettingsAck& as_decoded) {
  if (as_decoded.code != p::ResponseCode::kOk) return;
  std::lock_guard<std::mutex> lock(mutex_);
  const p::Conventions& c = codec_.conventions;
  if (!p::enhancement_fits(as_decoded, c.enhancement_switch)) {
    const p::ConventionInfo* info = p::find_convention("enhancement_switch");
    std::string fits;
    for (size_t i = 0; i < info->values.size(); ++i) {
      if (p::enhancement_fits(as_decoded, static_cast<p::EnhancementSwitch>(i)))
        fits += std::string(fits.empty() ? "" : " or ") + info->values[i];
    }
    const unsigned byte = (as_decoded.enhancement_on ? 0x80u : 0u) | as_decoded.enhancement_level;
    contradict("enhancement_switch", "ACK 0x010100 byte 10 = " + hex_byte(byte) +
                                         " has a level above 10 under enhancement_switch: " +
                                         info->get(*info, {crc_coverage_, codec_}) +
                                         (fits.empty() ? "" : "; it fits " + fits));
  }
  if (!p::thermal_zoom_fits(as_decoded.zoom_x, c.thermal_zoom_code)) {
    const bool ratio = c.thermal_zoom_code == p::ThermalZoomCode::kRatio;
    contradict("thermal_zoom_code", "ACK 0x010100 byte 4 zoom code " +
                                        std::to_string(as_decoded.zoom_x) +
                                        " is no ratio 1..8 under thermal_zoom_code: " +
                                        (ratio ? "ratio; it fits zero_based" : "zero_based"));
  }
}

void ConventionTracker::observe_calibration_acked(double now_s) {
  std::lock_guard<std::mutex> lock(mutex_);
  calibration_acked_s_ = now_s;
}

void ConventionTracker::observe_upgrade_status(const p::CameraUpgradeStatus& m, double now_s) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (!calibration_acked_s_ || m.state != p::CameraUpgradeState::kRepairing) {
    check_calibration(now_s);
    return;
  }
  char after[64];
  std::snprintf(after, sizeof after, "%.1f s", now_s - *calibration_acked_s_);
  calibration_acked_s_.reset();
  calibration_evidence(p::CalibrationEnd::kStatus, std::string("0x000008 'repairing' ") + after +
                                                       " after a calibration's OK ACK");
}

void ConventionTracker::check_calibration(double now_s) {
  if (!calibration_acked_s_ || now_s - *calibration_acked_s_ < kCalibrationQuietS) return;
  calibration_acked_s_.reset();
  calibration_evidence(p::CalibrationEnd::kAck,
                       "no 0x000008 'repairing' within 2.5 s of a calibration's OK ACK");
}

void ConventionTracker::calibration_evidence(p::CalibrationEnd seen, const std::string& evidence) {
  p::CalibrationEnd& end = codec_.conventions.calibration_end;
  const char* seen_name = seen == p::CalibrationEnd::kAck ? "ack" : "status";
  if (end == p::CalibrationEnd::kAuto) {
    detect("calibration_end", evidence + " (the pod's reading: " + seen_name + ")");
  } else if (end != seen) {
    contradict("calibration_end",
               evidence + ": the pod's calibrations end as calibration_end: " + seen_name +
                   " (or auto) says, not " + (end == p::CalibrationEnd::kAck ? "ack" : "status"));
  }
}

void ConventionTracker::observe_ack(p::MessageId ack_id, const uint8_t* payload, size_t size,
                                    const p::AckOrderSetting& in_force) {
  std::lock_guard<std::mutex> lock(mutex_);
  if (codec_.ack_byte_order_auto) {
    // The link's setting has seen this ACK already (the Dispatcher shows it every ACK first).
    if (!in_force.locked()) return;
    codec_.ack_byte_order = in_force.order();
    codec_.ack_byte_order_auto = false;
    detected_.emplace_back("ack_byte_order", std::string("auto: detected ") +
                                                 p::to_string(in_force.order()) + " from " +
                                                 in_force.evidence());
    return;  // the ACK that locked it confirms nothing more
  }
  p::AckOrderFit fit;
  p::fit_ack_byte_order(ack_id, payload, size, fit);
  if (!fit.tells()) return;
  const p::ByteOrder seen = fit.big ? p::ByteOrder::kBig : p::ByteOrder::kLittle;
  if (seen != codec_.ack_byte_order) {
    contradict("ack_byte_order", fit.evidence + " reads sensibly " + p::to_string(seen) +
                                     "-endian only: set ack_byte_order: " + p::to_string(seen));
    return;
  }
  for (const auto& c : confirmed_)
    if (c.first == "ack_byte_order") return;
  confirmed_.emplace_back("ack_byte_order", fit.evidence);
}

void ConventionTracker::observe_crc_coverage(p::CrcCoverage locked) {
  if (locked == p::CrcCoverage::kAuto) return;
  std::lock_guard<std::mutex> lock(mutex_);
  if (crc_coverage_ != p::CrcCoverage::kAuto) return;
  crc_coverage_ = locked;
  detect("crc_coverage", "the first frames' checksums");
}

p::GimbalAttitude ConventionTracker::applied(const p::GimbalAttitude& m) const {
  p::GimbalAttitude out = m;
  const p::Conventions c = conventions();
  p::attitude_from_wire(out, c, yaw_range());
  return out;
}

p::CameraSystemStatus ConventionTracker::applied(const p::CameraSystemStatus& m) const {
  p::CameraSystemStatus out = m;
  p::sd_capacities_from_wire(out, conventions());
  return out;
}

p::ThermalSettingsAck ConventionTracker::applied(const p::ThermalSettingsAck& m) const {
  p::ThermalSettingsAck out = m;
  const p::Conventions c = conventions();
  const p::Enhancement e = p::enhancement_from_wire(m, c.enhancement_switch);
  out.enhancement_on = e.on;
  out.enhancement_level = e.level;
  out.zoom_x = p::thermal_zoom_from_wire(m.zoom_x, c.thermal_zoom_code);
  return out;
}

std::vector<ConventionStatus> ConventionTracker::report() const {
  std::lock_guard<std::mutex> lock(mutex_);
  std::vector<ConventionStatus> out;
  for (const p::ConventionInfo& info : p::convention_table()) {
    ConventionStatus s;
    s.name = info.name;
    s.value = info.get(info, {crc_coverage_, codec_});
    s.source = from_parameters_.count(s.name) ? "parameter" : "default";
    for (const auto& d : detected_)
      if (d.first == s.name) s.source = d.second;
    for (const auto& c : confirmed_)
      if (c.first == s.name) s.source += ", confirmed by " + c.second;
    for (const auto& c : contradictions_)
      if (c.first == s.name) s.contradiction = c.second;
    out.push_back(std::move(s));
  }
  return out;
}

bool ConventionTracker::contradicted() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return !contradictions_.empty();
}

}  // namespace k40t::driver
