// The pod's state as the SKYPORT bridge sees it (pod_state_tracker.h), on hand-made report
// sequences: joints by name, the recording rules (a start the pod accepted, record/status going
// silent), the SD-full and recording events, the work mode the pod accepted, the state's age.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "k40t_driver/skyport/pod_state_tracker.h"

namespace k40t::driver::skyport {
namespace {

struct Rig {
  std::vector<std::string> events;
  PodStateTracker tracker{[this](const std::string& text) { events.push_back(text); }};
};

TEST(PodStateTracker, JointsByNameSuffixAndTheStateAge) {
  Rig rig;
  EXPECT_EQ(rig.tracker.snapshot(9.0).state_age_s, -1.0);  // nothing heard yet
  EXPECT_FALSE(rig.tracker.snapshot(9.0).have_joints);
  // Velocities shorter than the names: the pitch's is 0. Unknown joints are ignored.
  rig.tracker.joints({"k40t_yaw_joint", "k40t_roll_joint", "k40t_pitch_joint", "wheel"},
                     {0.1, 0.2, 0.3, 9.0}, {1.0, 2.0}, 9.5);
  const PodSnapshot s = rig.tracker.snapshot(10.0);
  EXPECT_TRUE(s.have_joints);
  EXPECT_DOUBLE_EQ(s.yaw_rad, 0.1);
  EXPECT_DOUBLE_EQ(s.roll_rad, 0.2);
  EXPECT_DOUBLE_EQ(s.pitch_rad, 0.3);
  EXPECT_DOUBLE_EQ(s.yaw_rate_rad_s, 1.0);
  EXPECT_DOUBLE_EQ(s.roll_rate_rad_s, 2.0);
  EXPECT_DOUBLE_EQ(s.pitch_rate_rad_s, 0.0);
  EXPECT_DOUBLE_EQ(s.state_age_s, 0.5);
  // The attitude alone is not a status the age counts (it comes with the joints).
  rig.tracker.attitude(0.01, -0.2, 1.5);
  const PodSnapshot a = rig.tracker.snapshot(11.0);
  EXPECT_TRUE(a.have_attitude);
  EXPECT_DOUBLE_EQ(a.attitude_pitch_rad, -0.2);
  EXPECT_DOUBLE_EQ(a.attitude_yaw_rad, 1.5);
  EXPECT_DOUBLE_EQ(a.state_age_s, 1.5);
}

TEST(PodStateTracker, AcceptedStartCountsUntilRecordStatusGoesSilent) {
  Rig rig;
  EXPECT_TRUE(rig.tracker.snapshot(100.0).recording_known);  // never started: known not recording
  rig.tracker.record_accepted(true, 100.0);
  EXPECT_TRUE(rig.tracker.snapshot(102.4).recording);  // 2.4 s < 2.5 s
  const PodSnapshot silent = rig.tracker.snapshot(102.6);
  EXPECT_FALSE(silent.recording);
  EXPECT_FALSE(silent.recording_known);  // started, never confirmed: may or may not record

  rig.tracker.record(true, 5, "recording", 103.0);
  EXPECT_TRUE(rig.tracker.snapshot(105.4).recording);
  EXPECT_EQ(rig.tracker.snapshot(105.4).record_duration_s, 5);
  EXPECT_FALSE(rig.tracker.snapshot(105.6).recording_known);  // record/status silent 2.6 s

  rig.tracker.record(false, 0, "stopped", 106.0);
  const PodSnapshot stopped = rig.tracker.snapshot(200.0);
  EXPECT_FALSE(stopped.recording);
  EXPECT_TRUE(stopped.recording_known);
  EXPECT_EQ(rig.events, (std::vector<std::string>{"K40T: recording started",
                                                  "K40T: recording stopped (stopped)"}));
}

TEST(PodStateTracker, AcceptedStopIsKnownAtOnce) {
  Rig rig;
  rig.tracker.record(true, 1, "recording", 10.0);
  rig.tracker.record_accepted(false, 10.5);
  const PodSnapshot s = rig.tracker.snapshot(10.6);
  EXPECT_FALSE(s.recording);
  EXPECT_TRUE(s.recording_known);
}

TEST(PodStateTracker, SdCardFullIsToldOncePerTransition) {
  Rig rig;
  CameraReport report;
  report.sd_state = kSdFull;
  report.sd_total_mb = 64000;
  rig.tracker.camera(report, 1.0);
  rig.tracker.camera(report, 2.0);  // still full: no second message
  report.sd_state = 0;              // SD_OK (after a format)
  rig.tracker.camera(report, 3.0);
  report.sd_state = kSdFull;
  rig.tracker.camera(report, 4.0);
  EXPECT_EQ(rig.events, (std::vector<std::string>{"K40T: SD card full", "K40T: SD card full"}));
  const PodSnapshot s = rig.tracker.snapshot(4.0);
  EXPECT_TRUE(s.have_camera);
  EXPECT_EQ(s.sd_state, kSdFull);
  EXPECT_DOUBLE_EQ(s.sd_total_mb, 64000);
}

TEST(PodStateTracker, AcceptedWorkModeIsAnsweredUntilTheReportAgrees) {
  Rig rig;
  CameraReport photo;  // video_mode false
  rig.tracker.camera(photo, 1.0);
  rig.tracker.video_mode_accepted(true);
  EXPECT_TRUE(rig.tracker.snapshot(1.1).video_mode);  // the report from before the set is old
  CameraReport video;
  video.video_mode = true;
  rig.tracker.camera(video, 1.5);  // agrees: the command is done
  rig.tracker.camera(photo, 2.0);  // changed since (another client)
  EXPECT_FALSE(rig.tracker.snapshot(2.0).video_mode);
}

TEST(PodStateTracker, PhotoAndRepairReportsAreCounted) {
  Rig rig;
  rig.tracker.photo(2);
  rig.tracker.photo(3);
  rig.tracker.repair(kRepairing, 40);
  rig.tracker.visible(4.0, 18.8, 5.0);
  const PodSnapshot s = rig.tracker.snapshot(5.0);
  EXPECT_EQ(s.photo_status_count, 2u);
  EXPECT_EQ(s.photo_state, 3);
  EXPECT_EQ(s.repair_status_count, 1u);
  EXPECT_EQ(s.repair_state, kRepairing);
  EXPECT_EQ(s.repair_percent, 40);
  EXPECT_TRUE(s.have_visible);
  EXPECT_DOUBLE_EQ(s.zoom_ratio, 4.0);
  EXPECT_DOUBLE_EQ(s.focal_length_mm, 18.8);
  EXPECT_DOUBLE_EQ(s.state_age_s, 0.0);
}

}  // namespace
}  // namespace k40t::driver::skyport
