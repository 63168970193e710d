// /diagnostics for the pod (diagnostic_updater), updated every ~diagnostic_period on a steady
// timer. The checks' levels and texts are the ROS-free driver/pod_health.h (link, self-test,
// stabilisation, SD card, temperature alarms, settings) and driver/convention_health.h
// (conventions); this adds the FrequencyStatus of each periodic report at the document's rate
// (0x000004 only while the pod measures temperatures) and the hardware id built from the versions
// read on connect.
#pragma once

#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include <diagnostic_updater/diagnostic_updater.h>
#include <diagnostic_updater/update_functions.h>
#include <ros/node_handle.h>
#include <ros/steady_timer.h>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/driver/pod_health.h"
#include "k40t_driver/driver/pod_queries.h"
#include "k40t_driver/driver/thermal_measurement_watch.h"
#include "k40t_driver/protocol/messages/camera_reports.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/ros/ros_params.h"
#include "k40t_driver/ros/settings_sync.h"

namespace k40t::driver {

class PodDiagnostics {
 public:
  // `settings` may be null (replay mode has no settings to read).
  PodDiagnostics(ros::NodeHandle nh, ros::NodeHandle private_nh, PodDriver& driver,
                 const RosPodConfig& config, const SettingsSync* settings);

  void set_versions(const PodVersions& versions);
  // Another part's status (e.g. TargetLocator's), updated with the others.
  void add_task(const std::string& name,
                std::function<void(diagnostic_updater::DiagnosticStatusWrapper&)> task) {
    updater_.add(name, std::move(task));
  }

 private:
  struct RateCheck {
    double min_hz = 0;
    double max_hz = 0;
    std::unique_ptr<diagnostic_updater::FrequencyStatus> status;
  };
  // `not_expected`, if given, returns why no report is due now (empty: due at rate_hz).
  template <class Msg>
  void add_rate_check(PodDriver& driver, const std::string& name, double rate_hz,
                      std::function<std::string()> not_expected = {});

  // Adds the task `name` whose status is what `check` computes at each update.
  void add_check(const std::string& name, std::function<HealthCheck()> check);
  // The same for a check of the latest report kept in `latest` (under mutex_).
  template <class Msg>
  void add_report_check(const std::string& name, const std::optional<Msg>& latest,
                        HealthCheck (*check)(const std::optional<Msg>&));
  void update();

  PodDriver& driver_;
  RosPodConfig config_;
  const SettingsSync* settings_;
  diagnostic_updater::Updater updater_;
  double period_s_;
  std::vector<std::unique_ptr<RateCheck>> rates_;
  ros::SteadyTimer timer_;

  std::mutex mutex_;  // the latest reports, written on the I/O thread
  std::optional<protocol::GimbalStatus> gimbal_;
  std::optional<protocol::CameraSystemStatus> camera_;
  std::optional<protocol::ThermalStatus> thermal_;
  using SteadyClock = std::chrono::steady_clock;
  SteadyClock::time_point thermal_at_{};  // when thermal_ came
  ThermalMeasurementWatch measurement_;
  std::string hardware_id_ = "K40T (versions not read)";
};

}  // namespace k40t::driver
