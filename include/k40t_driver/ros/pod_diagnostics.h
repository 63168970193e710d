// /diagnostics for the pod (diagnostic_updater), updated every ~diagnostic_period on a steady
// timer:
//   link               ERROR while the link is down or no frame came for silence_timeout (so a
//                      silent or unplugged pod is ERROR within silence_timeout + one period);
//                      every counter (bytes, frames, checksum and length errors, discarded
//                      bytes, unknown ids, sequence gaps, decode errors, requests, NACKs, ACK
//                      timeouts, retries, reconnects)
//   <name> report      FrequencyStatus of each periodic report at the document's rate
//   self-test          per sensor, from 0x000001; gimbal/camera link and upgrade state
//   stabilisation      from 0x000001
//   SD card            from 0x000003
//   temperature alarms from 0x000004
//   settings           dynamic_reconfigure read-back and refused changes
// The hardware id is built from the versions read on connect.
#pragma once

#include <memory>
#include <mutex>
#include <optional>
#include <vector>

#include <diagnostic_updater/diagnostic_updater.h>
#include <diagnostic_updater/update_functions.h>
#include <ros/node_handle.h>
#include <ros/steady_timer.h>

#include "k40t_driver/driver/pod_driver.h"
#include "k40t_driver/driver/pod_queries.h"
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
  template <class Msg>
  void add_rate_check(PodDriver& driver, const std::string& name, double rate_hz);

  void link(diagnostic_updater::DiagnosticStatusWrapper& stat);
  void self_test(diagnostic_updater::DiagnosticStatusWrapper& stat);
  void stabilisation(diagnostic_updater::DiagnosticStatusWrapper& stat);
  void sd_card(diagnostic_updater::DiagnosticStatusWrapper& stat);
  void alarms(diagnostic_updater::DiagnosticStatusWrapper& stat);
  void settings(diagnostic_updater::DiagnosticStatusWrapper& stat);
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
  std::string hardware_id_ = "K40T (versions not read)";
};

}  // namespace k40t::driver
