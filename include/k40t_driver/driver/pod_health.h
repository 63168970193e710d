// The pod diagnostics' checks, ROS-free: each turns the driver's counters or the latest report
// into a level, a one-line summary and the key/value pairs shown with it. ros/pod_diagnostics.h
// publishes them on /diagnostics (diagnostic_updater) and adds the report-rate checks.
//   link               the link's state (link_monitor.h) as the console tells it: WARN while
//                      starting or waiting for the first frame, ERROR when the device cannot be
//                      opened, nothing answers, the link is lost or no frame came for
//                      silence_timeout; every counter of the link, the parser, the session and
//                      the driver
//   self-test          per sensor, from 0x000001; gimbal/camera link and upgrade state
//   stabilisation      from 0x000001
//   SD card            from 0x000003
//   temperature alarms from 0x000004, while measuring and while it is fresh
//   settings           the settings read-back and refused changes
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/driver/settings_state.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/thermal.h"

namespace k40t::driver {

// The values of diagnostic_msgs/DiagnosticStatus's levels OK, WARN and ERROR.
enum class HealthLevel : uint8_t { kOk = 0, kWarn = 1, kError = 2 };

// A value keeps its type so that the glue formats it as diagnostic_updater formats that type.
using HealthValue = std::variant<std::string, bool, int64_t, uint64_t, double>;

struct HealthCheck {
  HealthLevel level = HealthLevel::kOk;
  std::string summary;
  std::vector<std::pair<std::string, HealthValue>> values;

  void set(HealthLevel new_level, std::string text) {
    level = new_level;
    summary = std::move(text);
  }
  // One overload per kind, so that a text never turns into a bool.
  void add(std::string key, std::string value) {
    values.emplace_back(std::move(key), std::move(value));
  }
  void add(std::string key, const char* value) { add(std::move(key), std::string(value)); }
  void add(std::string key, bool value) { values.emplace_back(std::move(key), value); }
  void add(std::string key, double value) { values.emplace_back(std::move(key), value); }
  template <class Int, std::enable_if_t<std::is_integral_v<Int>, int> = 0>
  void add(std::string key, Int value) {
    if constexpr (std::is_signed_v<Int>) {
      values.emplace_back(std::move(key), static_cast<int64_t>(value));
    } else {
      values.emplace_back(std::move(key), static_cast<uint64_t>(value));
    }
  }
  // The value of `key` (nullptr: not added).
  const HealthValue* value(const std::string& key) const;
};

// What the link check needs of the driver besides its counters.
struct LinkContext {
  bool replay = false;
  std::string device;              // the device URL (live)
  double silence_timeout_s = 0.5;  // longer without a frame: the pod is silent
  PodLinkReport link;              // the link's state (live)
};

HealthCheck link_health(const DriverStats& stats, const LinkContext& context);
HealthCheck self_test_health(const std::optional<protocol::GimbalStatus>& gimbal);
HealthCheck stabilisation_health(const std::optional<protocol::GimbalStatus>& gimbal);
HealthCheck sd_card_health(const std::optional<protocol::CameraSystemStatus>& camera);
// What the alarms check needs besides the last 0x000004: whether the pod measures (it sends no
// 0x000004 while it does not, section 3.2.2.4) and how old that report is.
struct ThermalContext {
  bool measuring = true;
  double report_age_s = 0;
};
// Older than this (5 report periods at the document's 5 Hz), a report's alarm flags are not shown.
inline constexpr double kThermalReportStaleS = 1.0;
HealthCheck alarms_health(const std::optional<protocol::ThermalStatus>& thermal,
                          const ThermalContext& context = {});
HealthCheck settings_health(const SettingsState& settings);

}  // namespace k40t::driver
