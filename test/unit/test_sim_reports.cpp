// The simulator's report cadence (document rates) and the status frames of model events.
#include <gtest/gtest.h>

#include <map>

#include "k40t_driver/protocol/messages/camera.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"
#include "sim_pod_harness.h"

namespace k40t::sim {
namespace {

namespace p = protocol;

// Runs the scheduler for `seconds` of model time and counts what it sends.
std::map<p::MessageId, int> run_reports(PodModel& pod, double seconds) {
  ReportScheduler scheduler;
  std::map<p::MessageId, int> sent;
  const int steps = static_cast<int>(std::lround(seconds / 0.01));
  for (int i = 0; i < steps; ++i) {
    for (const PeriodicReport* report : scheduler.due(pod, pod.now_s())) ++sent[report->id];
    pod.step(0.01);
  }
  return sent;
}

TEST(SimReports, RatesAreTheDocuments) {
  PodModel pod;
  pod.laser().set_periodic(true);
  const auto sent = run_reports(pod, 10.0);
  const std::map<p::MessageId, int> expected_per_10s = {
      {p::GimbalStatus::kId, 20},              // 2 Hz
      {p::GimbalAttitude::kId, 100},           // 10 Hz
      {p::CameraSystemStatus::kId, 10},        // 1 Hz
      {p::ThermalStatus::kId, 50},             // 5 Hz
      {p::VisibleStatus::kId, 50},             // 5 Hz
      {p::LaserPeriodicRangeStatus::kId, 10},  // 1 Hz while periodic ranging is on
  };
  for (const auto& [id, count] : expected_per_10s) {
    ASSERT_TRUE(sent.count(id)) << std::hex << id;
    EXPECT_EQ(sent.at(id), count) << std::hex << id;
  }
  for (const PeriodicReport& report : periodic_reports()) {
    EXPECT_TRUE(sent.count(report.id)) << "report 0x" << std::hex << report.id << " never sent";
  }
}

TEST(SimReports, CameraReportsStopWhileTheCameraIsDown) {
  PodConfig config;
  config.camera_boot_s = 3;
  PodModel pod(config);
  ASSERT_EQ(pod.shutdown(), Outcome::kOk);
  pod.step(0.5);
  const auto sent = run_reports(pod, 2.0);
  EXPECT_FALSE(sent.count(p::CameraSystemStatus::kId));
  EXPECT_EQ(sent.at(p::GimbalAttitude::kId), 20);  // the gimbal goes on
}

TEST(SimReports, CadenceHoldsAndAStallSendsOneReportNotABurst) {
  PodModel pod;
  ReportScheduler scheduler;
  const auto has = [](const std::vector<const PeriodicReport*>& due, p::MessageId id) {
    for (const PeriodicReport* r : due) {
      if (r->id == id) return true;
    }
    return false;
  };
  EXPECT_TRUE(has(scheduler.due(pod, 0.0), p::CameraSystemStatus::kId));
  EXPECT_FALSE(has(scheduler.due(pod, 0.5), p::CameraSystemStatus::kId));
  EXPECT_TRUE(has(scheduler.due(pod, 1.0), p::CameraSystemStatus::kId));
  // A stall of several periods sends one report, not a burst.
  const auto after_stall = scheduler.due(pod, 5.0);
  EXPECT_TRUE(has(after_stall, p::GimbalAttitude::kId));
  EXPECT_FALSE(has(scheduler.due(pod, 5.05), p::GimbalAttitude::kId));
  EXPECT_TRUE(has(scheduler.due(pod, 5.1), p::GimbalAttitude::kId));
}

TEST(SimReports, AttitudeReportCarriesTheModelsPose) {
  testing::PodHarness h;
  ASSERT_EQ(h.pod.gimbal().set_dial_speed(10, 10), Outcome::kOk);
  ASSERT_EQ(h.pod.gimbal().command_angles(-20.0, 30.0), Outcome::kOk);
  h.run(1.0);
  const auto attitude = h.report<p::GimbalAttitude>();
  EXPECT_NEAR(attitude.joint_yaw_deg, 10, 0.01);
  EXPECT_NEAR(attitude.joint_pitch_deg, -10, 0.01);
  EXPECT_NEAR(attitude.yaw_rate_deg_s, 10, 0.01);
  EXPECT_NEAR(attitude.pitch_rate_deg_s, -10, 0.01);
  EXPECT_NEAR(attitude.yaw_deg, 10, 0.01);
}

TEST(SimReports, MaintenanceEventsBecomeUpgradeReports) {
  testing::PodHarness h;
  ASSERT_EQ(h.pod.camera().start_tf_upgrade(), Outcome::kOk);
  h.run(10.5);
  const auto reports = h.status_frames<p::CameraUpgradeStatus>();
  ASSERT_EQ(reports.size(), 11u);
  EXPECT_EQ(reports[3].state, p::CameraUpgradeState::kUpgrading);
  EXPECT_EQ(reports[3].progress_percent, 30);
  EXPECT_EQ(reports.back().state, p::CameraUpgradeState::kSucceeded);
  const auto tf = h.status_frames<p::TfCardUpgradeStatus>();
  ASSERT_EQ(tf.size(), 2u);
  EXPECT_EQ(tf.back().state, p::TfUpgradeState::kSucceeded);
}

}  // namespace
}  // namespace k40t::sim
