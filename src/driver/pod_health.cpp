#include "k40t_driver/driver/pod_health.h"

#include <cstdio>
#include <initializer_list>
#include <utility>

namespace k40t::driver {

namespace p = protocol;

namespace {

const char* coverage_name(p::CrcCoverage coverage) {
  return coverage == p::CrcCoverage::kAuto ? "not locked yet" : p::to_string(coverage);
}

// The document's word for an enum value, or `unknown` for a code it does not list.
template <class E>
const char* name_or(E value, const char* unknown) {
  const char* name = p::to_string(value);
  return name ? name : unknown;
}

// A sensor's self-test result or an alarm, by name.
struct Flag {
  const char* name;
  bool set;
};

// The names of `flags` whose value is `set`, comma-separated.
std::string names_where(std::initializer_list<Flag> flags, bool set) {
  std::string list;
  for (const Flag& flag : flags) {
    if (flag.set == set) list += list.empty() ? flag.name : std::string(", ") + flag.name;
  }
  return list;
}

// One way a check can go wrong: when `found`, it gives the check's level and summary.
struct Problem {
  bool found;
  HealthLevel level;
  std::string summary;
};

// The first problem found, in the order given, decides the check; none: OK with `ok_summary`.
void set_first_problem(HealthCheck& check, std::initializer_list<Problem> problems,
                       const char* ok_summary) {
  for (const Problem& problem : problems) {
    if (problem.found) return check.set(problem.level, problem.summary);
  }
  check.set(HealthLevel::kOk, ok_summary);
}

// The check `judge(report, check)` gives, or a warning while no `what` report has come.
template <class Report, class Judge>
HealthCheck when_reported(const std::optional<Report>& report, const char* what, Judge judge) {
  HealthCheck check;
  if (!report) {
    check.set(HealthLevel::kWarn, std::string("no ") + what + " report yet");
  } else {
    judge(*report, check);
  }
  return check;
}

}  // namespace

const HealthValue* HealthCheck::value(const std::string& key) const {
  for (const auto& [name, v] : values) {
    if (name == key) return &v;
  }
  return nullptr;
}

HealthCheck link_health(const DriverStats& s, const LinkContext& context) {
  HealthCheck check;
  const transport::LinkState state = s.session.link_state;
  const double silent = s.seconds_since_last_frame;
  if (context.replay) {
    check.set(HealthLevel::kOk, silent < 0 ? "replay: no frame yet" : "replay");
  } else if (context.link.state != PodLink::kConnected) {
    const bool on_the_way =
        context.link.state == PodLink::kStarting || context.link.state == PodLink::kWaiting;
    check.set(on_the_way ? HealthLevel::kWarn : HealthLevel::kError, context.link.text);
  } else if (silent > context.silence_timeout_s) {
    char text[64];
    std::snprintf(text, sizeof text, "pod silent for %.1f s", silent);
    check.set(HealthLevel::kError, text);
  } else {
    check.set(HealthLevel::kOk, "connected, receiving");
  }
  const p::ParserStats& parser = s.session.parser;
  check.add("device", context.replay ? std::string("replay of raw/rx") : context.device);
  check.add("link state", context.replay ? "replay" : to_string(context.link.state));
  check.add("transport state", transport::to_string(state));
  check.add("last error", s.session.link.last_error);
  check.add("seconds since last frame", silent);
  check.add("crc coverage", coverage_name(s.crc_coverage));
  // The counters of the parser, the link, the session and the driver.
  const std::pair<const char*, uint64_t> counters[] = {
      {"bytes received", parser.bytes_received},
      {"bytes sent", s.session.link.bytes_sent},
      {"frames received", parser.frames_good},
      {"frames sent", s.session.frames_sent},
      {"checksum errors", parser.checksum_errors},
      {"length errors", parser.length_errors},
      {"bytes discarded", parser.bytes_discarded},
      {"unknown ids", parser.unknown_ids},
      {"sequence gaps", parser.sequence_gaps},
      {"frames lost", parser.frames_lost},
      {"frames repeated", parser.frames_repeated},
      {"decode errors", s.session.decode_errors},
      {"requests", s.session.requests},
      {"acks", s.session.acks},
      {"nacks", s.session.nacks},
      {"ack timeouts", s.session.ack_timeouts},
      {"retries", s.session.retries},
      {"late acks", s.session.late_acks},
      {"connects", s.session.link.connects},
      {"disconnects", s.session.link.disconnects},
      {"pod online events", s.pod_online_events},
      {"time syncs sent", s.time_syncs_sent},
      {"gps requests answered", s.gps_requests_answered},
      {"gps requests without fix", s.gps_requests_unanswerable},
      {"gps requests time-matched", s.gps_requests_time_matched},
      {"gps requests outside the history", s.gps_requests_out_of_history},
  };
  for (const auto& [name, count] : counters) check.add(name, count);
  check.add("last geotag gap to a fix (s)", s.last_geotag_gap_s);
  check.add("cmd_rate dead-man stops", s.deadman_stops);
  return check;
}

HealthCheck self_test_health(const std::optional<p::GimbalStatus>& gimbal) {
  return when_reported(gimbal, "gimbal status", [](const auto& g, HealthCheck& check) {
    const std::initializer_list<Flag> sensors = {
        {"thermal", g.ir_ok}, {"tele", g.tele_ok}, {"wide", g.wide_ok}, {"laser", g.laser_ok}};
    for (const Flag& sensor : sensors) check.add(sensor.name, sensor.set ? "passed" : "FAILED");
    const std::string failed = names_where(sensors, false);
    const bool links_ok = g.gimbal_link == p::GimbalLinkState::kNormal &&
                          g.camera_link == p::GimbalLinkState::kNormal;
    check.add("gimbal link", name_or(g.gimbal_link, "unknown"));
    check.add("camera link", name_or(g.camera_link, "unknown"));
    check.add("upgrade", name_or(g.upgrade, "unknown"));
    set_first_problem(check,
                      {{!failed.empty(), HealthLevel::kError, "self-test failed: " + failed},
                       {!links_ok, HealthLevel::kError, "gimbal or camera connection abnormal"},
                       {g.upgrade != p::GimbalUpgradeState::kNormal, HealthLevel::kWarn,
                        "firmware upgrade not completed"}},
                      "all sensors passed");
  });
}

HealthCheck stabilisation_health(const std::optional<p::GimbalStatus>& gimbal) {
  return when_reported(gimbal, "gimbal status", [](const auto& g, HealthCheck& check) {
    const bool trouble = g.stabilisation == p::GimbalStabilisationState::kFailed ||
                         g.stabilisation == p::GimbalStabilisationState::kFeatureLost;
    check.set(trouble ? HealthLevel::kWarn : HealthLevel::kOk,
              name_or(g.stabilisation, "unknown state"));
    check.add("state code", static_cast<int>(g.stabilisation));
  });
}

HealthCheck sd_card_health(const std::optional<p::CameraSystemStatus>& camera) {
  return when_reported(camera, "camera status", [](const auto& c, HealthCheck& check) {
    HealthLevel level = HealthLevel::kOk;
    switch (c.sd_state) {
      case p::SdCardState::kNormal:
        break;
      case p::SdCardState::kAbnormal:
      case p::SdCardState::kFormatError:
        level = HealthLevel::kError;
        break;
      default:
        level = HealthLevel::kWarn;
        break;  // slow, missing, full, undocumented
    }
    check.set(level, name_or(c.sd_state, "unknown SD card state"));
    check.add("total MB", c.sd_total_mb);
    check.add("free MB", c.sd_free_mb);
    check.add("used MB", c.sd_used_mb);
  });
}

HealthCheck alarms_health(const std::optional<p::ThermalStatus>& thermal,
                          const ThermalContext& context) {
  HealthCheck check;
  // The last flags are the pod's no more: measuring off, or the reports stopped.
  if (!context.measuring) {
    check.set(HealthLevel::kOk, "temperature measurement off: no alarms (no 0x000004)");
    return check;
  }
  if (thermal && context.report_age_s > kThermalReportStaleS) {
    char text[80];
    std::snprintf(text, sizeof text, "no thermal report for %.1f s: alarms unknown",
                  context.report_age_s);
    check.set(HealthLevel::kWarn, text);
    return check;
  }
  return when_reported(thermal, "thermal", [](const auto& t, HealthCheck& check) {
    const std::initializer_list<Flag> alarms = {{"high temperature", t.high_alarm},
                                                {"low temperature", t.low_alarm},
                                                {"temperature difference", t.difference_alarm},
                                                {"threshold", t.threshold_alarm}};
    for (const Flag& alarm : alarms) check.add(alarm.name, alarm.set);
    const std::string active = names_where(alarms, true);
    check.add("max degC", t.max_degC);
    check.add("min degC", t.min_degC);
    set_first_problem(check, {{!active.empty(), HealthLevel::kWarn, "alarm: " + active}},
                      "no alarm");
  });
}

HealthCheck settings_health(const SettingsState& s) {
  HealthCheck check;
  set_first_problem(
      check,
      {{s.reads == 0, HealthLevel::kWarn, "settings not read from the pod yet"},
       {!s.read_ok, HealthLevel::kWarn, "settings read-back incomplete: " + s.read_message},
       {!s.last_refusal.empty(), HealthLevel::kWarn,
        "last change refused and reverted: " + s.last_refusal}},
      "in sync with the pod");
  check.add("read-backs", s.reads);
  check.add("last read-back", s.read_message);
  check.add("changes applied", s.changes_applied);
  check.add("changes refused", s.changes_refused);
  check.add("last refusal", s.last_refusal);
  return check;
}

}  // namespace k40t::driver
