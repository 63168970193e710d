// The diagnostics' levels and texts (driver/pod_health.h), without ROS: which level each state of
// the link and each report gives, the summary it is shown with, and that the values keep their
// types (a text never becomes a bool).
#include <gtest/gtest.h>

#include <string>
#include <utility>

#include "k40t_driver/driver/pod_health.h"

namespace k40t::driver {
namespace {

namespace p = protocol;

DriverStats connected_stats(double seconds_since_last_frame) {
  DriverStats s;
  s.session.link_state = transport::LinkState::kConnected;
  s.seconds_since_last_frame = seconds_since_last_frame;
  return s;
}

LinkContext live(double silence_timeout_s = 0.5) {
  LinkContext c;
  c.device = "serial:///dev/ttyUSB0?baud=115200";
  c.silence_timeout_s = silence_timeout_s;
  c.link = PodLinkReport{PodLink::kConnected, "connected to the pod at serial:///dev/ttyUSB0"};
  return c;
}

// A check's level with its summary: one expectation per state, and a failure shows both.
using Shown = std::pair<HealthLevel, std::string>;
Shown shown(const HealthCheck& check) {
  return {check.level, check.summary};
}

template <class T>
T value_of(const HealthCheck& check, const std::string& key) {
  const HealthValue* v = check.value(key);
  EXPECT_NE(v, nullptr) << key;
  if (!v) return T{};
  EXPECT_TRUE(std::holds_alternative<T>(*v)) << key << " holds another type";
  return std::holds_alternative<T>(*v) ? std::get<T>(*v) : T{};
}

TEST(PodHealthLink, LevelFollowsTheLinkAndTheSilence) {
  EXPECT_EQ(shown(link_health(connected_stats(0.1), live())),
            Shown(HealthLevel::kOk, "connected, receiving"));
  // Silent longer than silence_timeout: ERROR, the silence to 0.1 s.
  const HealthCheck silent = link_health(connected_stats(0.84), live());
  EXPECT_EQ(shown(silent), Shown(HealthLevel::kError, "pod silent for 0.8 s"));
  // The same silence under a longer timeout is fine.
  EXPECT_EQ(link_health(connected_stats(0.84), live(1.0)).level, HealthLevel::kOk);
}

// The check says what the console says (link_monitor.h): a warning on the way up, an error for
// each state that needs the user.
TEST(PodHealthLink, TheLinkStateDecidesAndIsShown) {
  const std::pair<PodLinkReport, HealthLevel> cases[] = {
      {{PodLink::kStarting, "starting the link to the pod at udp://10.0.0.2:2000"},
       HealthLevel::kWarn},
      {{PodLink::kWaiting, "waiting for the pod at udp://10.0.0.2:2000"}, HealthLevel::kWarn},
      {{PodLink::kNoAnswer,
        "waiting for the pod at udp://10.0.0.2:2000: nothing has answered for 3.0 s"},
       HealthLevel::kError},
      {{PodLink::kCannotOpen, "cannot open serial:///dev/ttyUSB0: No such file (retrying)"},
       HealthLevel::kError},
      {{PodLink::kLost, "link to the pod at tcp://10.0.0.2:2000 lost: reset; reconnecting"},
       HealthLevel::kError},
  };
  for (const auto& [report, level] : cases) {
    LinkContext context = live();
    context.link = report;
    DriverStats s = connected_stats(-1);
    s.session.link_state = transport::LinkState::kReconnecting;
    const HealthCheck check = link_health(s, context);
    EXPECT_EQ(shown(check), Shown(level, report.text));
    EXPECT_EQ(value_of<std::string>(check, "link state"), to_string(report.state));
    EXPECT_EQ(value_of<std::string>(check, "transport state"), "reconnecting");
  }
}

TEST(PodHealthLink, ReplayIsAlwaysOk) {
  LinkContext replay;
  replay.replay = true;
  DriverStats s;  // closed link, no frame: in replay that is just "no frame yet"
  HealthCheck check = link_health(s, replay);
  EXPECT_EQ(shown(check), Shown(HealthLevel::kOk, "replay: no frame yet"));
  EXPECT_EQ(value_of<std::string>(check, "device"), "replay of raw/rx");
  s.seconds_since_last_frame = 30;
  EXPECT_EQ(link_health(s, replay).summary, "replay");
}

TEST(PodHealthLink, CountersKeepTheirNamesAndTypes) {
  DriverStats s = connected_stats(0.2);
  s.session.parser.checksum_errors = 7;
  s.session.link.connects = 3;
  s.deadman_stops = 2;
  s.last_geotag_gap_s = 0.05;
  const HealthCheck check = link_health(s, live());
  EXPECT_EQ(value_of<std::string>(check, "device"), "serial:///dev/ttyUSB0?baud=115200");
  EXPECT_EQ(value_of<uint64_t>(check, "checksum errors"), 7u);
  EXPECT_EQ(value_of<uint64_t>(check, "connects"), 3u);
  EXPECT_EQ(value_of<uint64_t>(check, "cmd_rate dead-man stops"), 2u);
  EXPECT_DOUBLE_EQ(value_of<double>(check, "last geotag gap to a fix (s)"), 0.05);
  EXPECT_DOUBLE_EQ(value_of<double>(check, "seconds since last frame"), 0.2);
  EXPECT_EQ(value_of<std::string>(check, "crc coverage"), "not locked yet");
  EXPECT_EQ(check.value("no such key"), nullptr);
}

TEST(PodHealthSelfTest, FailedSensorsAreNamedInOrder) {
  EXPECT_EQ(shown(self_test_health(std::nullopt)),
            Shown(HealthLevel::kWarn, "no gimbal status report yet"));
  p::GimbalStatus g;
  EXPECT_EQ(shown(self_test_health(g)), Shown(HealthLevel::kOk, "all sensors passed"));
  g.laser_ok = false;
  g.tele_ok = false;
  const HealthCheck failed = self_test_health(g);
  EXPECT_EQ(shown(failed), Shown(HealthLevel::kError, "self-test failed: tele, laser"));
  EXPECT_EQ(value_of<std::string>(failed, "laser"), "FAILED");
  EXPECT_EQ(value_of<std::string>(failed, "thermal"), "passed");
}

TEST(PodHealthSelfTest, LinksAndUpgrade) {
  p::GimbalStatus g;
  g.camera_link = p::GimbalLinkState::kAbnormal;
  EXPECT_EQ(shown(self_test_health(g)),
            Shown(HealthLevel::kError, "gimbal or camera connection abnormal"));
  g.camera_link = p::GimbalLinkState::kNormal;
  g.upgrade = p::GimbalUpgradeState::kFirmwareUpgradeIncomplete;
  EXPECT_EQ(shown(self_test_health(g)),
            Shown(HealthLevel::kWarn, "firmware upgrade not completed"));
  g.upgrade = static_cast<p::GimbalUpgradeState>(9);  // not in the document
  EXPECT_EQ(value_of<std::string>(self_test_health(g), "upgrade"), "unknown");
}

TEST(PodHealthStabilisation, FailureAndLostFeaturesWarn) {
  EXPECT_EQ(stabilisation_health(std::nullopt).level, HealthLevel::kWarn);
  p::GimbalStatus g;
  for (auto [state, level] : {std::pair{p::GimbalStabilisationState::kOff, HealthLevel::kOk},
                              {p::GimbalStabilisationState::kStabilising, HealthLevel::kOk},
                              {p::GimbalStabilisationState::kFailed, HealthLevel::kWarn},
                              {p::GimbalStabilisationState::kFeatureLost, HealthLevel::kWarn}}) {
    g.stabilisation = state;
    const HealthCheck check = stabilisation_health(g);
    EXPECT_EQ(check.level, level) << static_cast<int>(state);
    EXPECT_EQ(check.summary, p::to_string(state));
    EXPECT_EQ(value_of<int64_t>(check, "state code"), static_cast<int64_t>(state));
  }
  g.stabilisation = static_cast<p::GimbalStabilisationState>(7);
  EXPECT_EQ(stabilisation_health(g).summary, "unknown state");
}

TEST(PodHealthSdCard, AbnormalAndFormatErrorsAreErrors) {
  EXPECT_EQ(sd_card_health(std::nullopt).summary, "no camera status report yet");
  p::CameraSystemStatus c;
  c.sd_free_mb = 1024;
  const struct {
    p::SdCardState state;
    HealthLevel level;
  } cases[] = {{p::SdCardState::kNormal, HealthLevel::kOk},
               {p::SdCardState::kAbnormal, HealthLevel::kError},
               {p::SdCardState::kSlow, HealthLevel::kWarn},
               {p::SdCardState::kMissing, HealthLevel::kWarn},
               {p::SdCardState::kFull, HealthLevel::kWarn},
               {p::SdCardState::kFormatError, HealthLevel::kError},
               {static_cast<p::SdCardState>(6), HealthLevel::kWarn}};
  for (const auto& c_case : cases) {
    c.sd_state = c_case.state;
    EXPECT_EQ(sd_card_health(c).level, c_case.level) << static_cast<int>(c_case.state);
  }
  EXPECT_EQ(sd_card_health(c).summary, "unknown SD card state");
  EXPECT_DOUBLE_EQ(value_of<double>(sd_card_health(c), "free MB"), 1024);
}

TEST(PodHealthAlarms, ActiveAlarmsAreListed) {
  EXPECT_EQ(alarms_health(std::nullopt).summary, "no thermal report yet");
  p::ThermalStatus t;
  EXPECT_EQ(shown(alarms_health(t)), Shown(HealthLevel::kOk, "no alarm"));
  t.high_alarm = true;
  t.threshold_alarm = true;
  const HealthCheck check = alarms_health(t);
  EXPECT_EQ(shown(check), Shown(HealthLevel::kWarn, "alarm: high temperature, threshold"));
  EXPECT_TRUE(value_of<bool>(check, "high temperature"));
  EXPECT_FALSE(value_of<bool>(check, "low temperature"));
}

// Section 3.2.2.4: with measurement off the pod stops 0x000004, so its last flags are not the
// pod's any more; neither are those of a report that stopped coming.
TEST(PodHealthAlarms, NoFlagsWhileNotMeasuringOrWhenStale) {
  p::ThermalStatus t;
  t.high_alarm = true;
  ThermalContext off;
  off.measuring = false;
  const HealthCheck not_measuring = alarms_health(t, off);
  EXPECT_EQ(shown(not_measuring),
            Shown(HealthLevel::kOk, "temperature measurement off: no alarms (no 0x000004)"));
  EXPECT_EQ(not_measuring.value("high temperature"), nullptr);
  EXPECT_EQ(shown(alarms_health(std::nullopt, off)).first, HealthLevel::kOk);

  ThermalContext stale;
  stale.report_age_s = 2.5;
  const HealthCheck old = alarms_health(t, stale);
  EXPECT_EQ(shown(old), Shown(HealthLevel::kWarn, "no thermal report for 2.5 s: alarms unknown"));
  EXPECT_EQ(old.value("high temperature"), nullptr);
  ThermalContext fresh;
  fresh.report_age_s = 0.2;
  EXPECT_EQ(shown(alarms_health(t, fresh)), Shown(HealthLevel::kWarn, "alarm: high temperature"));
}

TEST(PodHealthSettings, EachStateHasItsText) {
  SettingsState s;
  EXPECT_EQ(shown(settings_health(s)),
            Shown(HealthLevel::kWarn, "settings not read from the pod yet"));
  s.reads = 1;
  s.read_message = "thermal_get_settings: ACK timeout";
  EXPECT_EQ(settings_health(s).summary,
            "settings read-back incomplete: thermal_get_settings: ACK timeout");
  s.read_ok = true;
  s.last_refusal = "palette: NACK";
  EXPECT_EQ(shown(settings_health(s)),
            Shown(HealthLevel::kWarn, "last change refused and reverted: palette: NACK"));
  s.last_refusal.clear();
  s.changes_applied = 4;
  const HealthCheck ok = settings_health(s);
  EXPECT_EQ(shown(ok), Shown(HealthLevel::kOk, "in sync with the pod"));
  EXPECT_EQ(value_of<uint64_t>(ok, "changes applied"), 4u);
  EXPECT_EQ(value_of<uint64_t>(ok, "read-backs"), 1u);
}

}  // namespace
}  // namespace k40t::driver
