// The simulated camera system (section 3.2.4): mode rules and refusal codes, photo and record
// status sequences, the SD card, the clock and file names, GPS per photo.
#include <gtest/gtest.h>

#include "k40t_driver/sim/camera_model.h"
#include "sim_test_util.h"

namespace k40t::sim {
namespace {

using testing::events_of;
using testing::states_of;

// CameraModel::step has an extra argument (optics busy).
struct Stepper {
  CameraModel& camera;
  void step(double dt, EventQueue& events) { camera.step(dt, false, events); }
};
void run(CameraModel& camera, double seconds, EventQueue& events) {
  Stepper stepper{camera};
  testing::advance(stepper, seconds, events);
}

CameraConfig small_card(double capacity_mb) {
  CameraConfig config;
  config.sd.capacity_mb = capacity_mb;
  config.sd.full_reserve_mb = 5;
  return config;
}

// A camera with the default configuration and the queue its events go to.
class SimCamera : public ::testing::Test {
 protected:
  CameraModel camera;
  EventQueue events;
};

TEST_F(SimCamera, PhotoInVideoModeAndRecordingInPhotoModeAreRefused) {
  EXPECT_EQ(camera.start_recording(0, "", ""), Outcome::kFailure);  // photo mode
  ASSERT_EQ(camera.set_capture_mode(CaptureMode::kVideo), Outcome::kOk);
  EXPECT_EQ(camera.take_photo(0, "", ""), Outcome::kFailure);
  ASSERT_EQ(camera.start_recording(2, "", ""), Outcome::kOk);
  EXPECT_EQ(camera.take_photo(0, "", ""), Outcome::kRecording);
  EXPECT_EQ(camera.set_capture_mode(CaptureMode::kPhoto), Outcome::kRecording);
  EXPECT_EQ(camera.format_sd(), Outcome::kRecording);
  EXPECT_EQ(camera.start_recording(2, "", ""), Outcome::kBusy);  // a repeated start
  ASSERT_EQ(camera.stop_recording(), Outcome::kOk);
  run(camera, 0.1, events);
  EXPECT_EQ(camera.stop_recording(), Outcome::kFailure);

  ASSERT_EQ(camera.set_capture_mode(CaptureMode::kPhoto), Outcome::kOk);
  ASSERT_EQ(camera.set_photo_mode(PhotoMode::kTimeLapse, 5, 3), Outcome::kOk);
  ASSERT_EQ(camera.take_photo(0, "", ""), Outcome::kOk);
  EXPECT_EQ(camera.take_photo(0, "", ""), Outcome::kPhotoInProgress);
  EXPECT_EQ(camera.start_recording(0, "", ""), Outcome::kPhotoInProgress);
  EXPECT_EQ(camera.set_capture_mode(CaptureMode::kVideo), Outcome::kPhotoInProgress);
  EXPECT_EQ(camera.set_photo_mode(PhotoMode::kSingle, 5, 3), Outcome::kPhotoInProgress);
}

TEST_F(SimCamera, CardConditionsRefuseWithTheirCodes) {
  camera.sd().remove();
  EXPECT_EQ(camera.take_photo(0, "", ""), Outcome::kNoSdCard);
  EXPECT_EQ(camera.format_sd(), Outcome::kNoSdCard);
  EXPECT_EQ(camera.sd().state(), SdState::kAbsent);
  camera.sd().insert();
  camera.sd().fill();
  EXPECT_EQ(camera.sd().state(), SdState::kFull);
  EXPECT_EQ(camera.take_photo(0, "", ""), Outcome::kNoSpace);
  ASSERT_EQ(camera.format_sd(), Outcome::kOk);
  EXPECT_EQ(camera.take_photo(0, "", ""), Outcome::kBusy);  // formatting
  EXPECT_EQ(camera.format_sd(), Outcome::kBusy);
}

TEST_F(SimCamera, PhotoModeParametersAreChecked) {
  EXPECT_EQ(camera.set_photo_mode(PhotoMode::kBurst, 0, 4), Outcome::kFailure);
  EXPECT_EQ(camera.set_photo_mode(PhotoMode::kTimeLapse, 6, 0), Outcome::kFailure);
  ASSERT_EQ(camera.set_photo_mode(PhotoMode::kBurst, 0, 5), Outcome::kOk);
  EXPECT_EQ(camera.settings().burst_count, 5);
  EXPECT_EQ(camera.settings().time_lapse_interval_s, 5);  // unchanged default
}

TEST(SimCameraSmallCard, SdCardFillsWithPhotosUntilNoSpace) {
  CameraModel camera(small_card(60));  // 4000x3000 visible 6 MB + IR 1 MB per photo
  EventQueue events;
  int taken = 0;
  for (int i = 0; i < 20; ++i) {
    const Outcome outcome = camera.take_photo(0, "", "");
    if (outcome != Outcome::kOk) {
      EXPECT_EQ(outcome, Outcome::kNoSpace);
      break;
    }
    run(camera, 0.6, events);
    ++taken;
  }
  // 8 x 7 MB = 56 MB; the 4 MB left are under the 5 MB reserve: the card reads full.
  EXPECT_EQ(taken, 8);
  EXPECT_NEAR(camera.sd().used_mb(), 56, 1e-9);
  EXPECT_EQ(camera.photos().size(), 8u);
  EXPECT_EQ(camera.sd().state(), SdState::kFull);
}

TEST_F(SimCamera, SingleShotSendsNoStatusFrameButAsksForGps) {
  ASSERT_EQ(camera.take_photo(2, "", ""), Outcome::kOk);
  run(camera, 1.0, events);
  EXPECT_TRUE(events_of<PhotoStatusEvent>(events).empty());  // section 3.2.4.3
  ASSERT_EQ(events_of<GpsRequestEvent>(events).size(), 1u);
  EXPECT_EQ(camera.photos().size(), 1u);
  EXPECT_FALSE(camera.shooting());

  CameraConfig config;
  config.single_shot_status = true;
  CameraModel chatty(config);
  EventQueue more;
  ASSERT_EQ(chatty.take_photo(2, "", ""), Outcome::kOk);
  run(chatty, 1.0, more);
  const auto status = events_of<PhotoStatusEvent>(more);
  ASSERT_EQ(status.size(), 2u);
  EXPECT_EQ(status[0].state, PhotoState::kSingleInProgress);
  EXPECT_EQ(status[1].state, PhotoState::kTaken);
  EXPECT_EQ(status[1].count, 1);
}

TEST_F(SimCamera, BurstReportsEachShotThenDone) {
  ASSERT_EQ(camera.set_photo_mode(PhotoMode::kBurst, 0, 3), Outcome::kOk);
  ASSERT_EQ(camera.take_photo(1, "survey", "roof"), Outcome::kOk);
  run(camera, 2.0, events);
  const auto status = events_of<PhotoStatusEvent>(events);
  ASSERT_EQ(status.size(), 4u);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(status[i].state, PhotoState::kBurstInProgress);
    EXPECT_EQ(status[i].count, i + 1);
    EXPECT_EQ(status[i].lens_mode, 1);
  }
  EXPECT_EQ(status[3].state, PhotoState::kTaken);
  EXPECT_EQ(status[3].count, 3);
  EXPECT_EQ(events_of<GpsRequestEvent>(events).size(), 3u);
  ASSERT_EQ(camera.photos().size(), 3u);
  EXPECT_EQ(camera.photos()[0].path, "survey/roof_1.jpg");
  EXPECT_EQ(camera.photos()[2].path, "survey/roof_3.jpg");
}

TEST_F(SimCamera, TimeLapseShootsEveryIntervalUntilStopped) {
  ASSERT_EQ(camera.set_photo_mode(PhotoMode::kTimeLapse, 7, 0), Outcome::kOk);
  ASSERT_EQ(camera.take_photo(0, "", ""), Outcome::kOk);
  run(camera, 15.0, events);  // shots at 0, 7, 14 s
  EXPECT_EQ(camera.photos().size(), 3u);
  ASSERT_EQ(camera.stop_photo(), Outcome::kOk);
  run(camera, 0.1, events);
  const auto status = events_of<PhotoStatusEvent>(events);
  ASSERT_EQ(status.size(), 4u);
  EXPECT_EQ(status[2].state, PhotoState::kTimeLapseInProgress);
  EXPECT_EQ(status[2].count, 3);
  EXPECT_EQ(status[3].state, PhotoState::kStopped);
  EXPECT_EQ(camera.stop_photo(), Outcome::kFailure);
}

TEST(SimCameraSmallCard, RecordingReportsSecondsAtOneHertzAndFillsTheCard) {
  CameraModel camera(small_card(100));
  EventQueue events;
  ASSERT_EQ(camera.set_capture_mode(CaptureMode::kVideo), Outcome::kOk);
  // Visible 1080p at 8 Mbit/s = 1 MB/s; the card fills (95 MB usable) after ~95 s.
  ASSERT_EQ(camera.start_recording(2, "", "flight"), Outcome::kOk);
  run(camera, 10.05, events);
  auto status = events_of<RecordStatusEvent>(events);
  ASSERT_EQ(status.size(), 11u);  // 0 s, then 1..10 s
  for (size_t i = 0; i < status.size(); ++i) {
    EXPECT_EQ(status[i].state, RecordState::kRecording);
    EXPECT_EQ(status[i].seconds, i);
  }
  EXPECT_NEAR(camera.sd().used_mb(), 10.05, 0.01);
  run(camera, 100.0, events);
  EXPECT_FALSE(camera.recording());
  status = events_of<RecordStatusEvent>(events);
  EXPECT_EQ(status.back().state, RecordState::kSdFull);
  EXPECT_NEAR(status.back().seconds, 95, 1);
  EXPECT_EQ(camera.sd().state(), SdState::kFull);
  ASSERT_EQ(camera.videos().size(), 1u);
  EXPECT_EQ(camera.videos()[0].path, "flight.mp4");
}

TEST_F(SimCamera, FormatReportsProgressAtFiveHertzAndEmptiesTheCard) {
  ASSERT_EQ(camera.take_photo(0, "", ""), Outcome::kOk);
  run(camera, 1.0, events);
  ASSERT_GT(camera.sd().used_mb(), 0);
  ASSERT_EQ(camera.format_sd(), Outcome::kOk);
  run(camera, 2.5, events);
  const auto status = events_of<FormatStatusEvent>(events);
  ASSERT_GE(status.size(), 10u);  // 2 s at 5 Hz
  EXPECT_LE(status.size(), 12u);
  for (size_t i = 0; i + 1 < status.size(); ++i)
    EXPECT_EQ(status[i].state, FormatState::kInProgress);
  EXPECT_EQ(status.back().state, FormatState::kDone);
  EXPECT_DOUBLE_EQ(camera.sd().used_mb(), 0);
  EXPECT_TRUE(camera.photos().empty());
}

TEST_F(SimCamera, FileNamesUseTheSyncedLocalTime) {
  // 2025-03-04T05:06:07.089Z, an hour east of Greenwich (tz_minuteswest -60).
  camera.clock().sync(1741064767089, -60, 0);
  ASSERT_EQ(camera.take_photo(2, "", ""), Outcome::kOk);
  run(camera, 0.01, events);
  ASSERT_EQ(camera.photos().size(), 1u);
  EXPECT_EQ(camera.photos()[0].path, "IMG_20250304_060607_099.jpg");
  const auto gps = events_of<GpsRequestEvent>(events);
  ASSERT_EQ(gps.size(), 1u);
  EXPECT_EQ(gps[0].time.hour, 5);  // the GPS request is in UTC
  EXPECT_EQ(gps[0].time.minute, 6);
  EXPECT_EQ(gps[0].time.second, 7);
  EXPECT_EQ(gps[0].time.millisecond, 99);
}

TEST_F(SimCamera, GpsAnswerIsRecordedWithThePhoto) {
  ASSERT_EQ(camera.take_photo(0, "", ""), Outcome::kOk);
  run(camera, 0.1, events);
  const auto requests = events_of<GpsRequestEvent>(events);
  ASSERT_EQ(requests.size(), 1u);
  GpsAnswer answer;
  answer.position.latitude_deg = 47.5;
  answer.position.longitude_deg = 8.25;
  EXPECT_TRUE(camera.attach_gps(requests[0].photo_id, answer));
  EXPECT_FALSE(camera.attach_gps(requests[0].photo_id + 1, answer));
  ASSERT_TRUE(camera.photos()[0].gps);
  EXPECT_DOUBLE_EQ(camera.photos()[0].gps->position.latitude_deg, 47.5);
}

TEST_F(SimCamera, BacklightAndStrongLightExcludeEachOther) {
  ASSERT_EQ(camera.set_backlight(true, 40), Outcome::kOk);
  EXPECT_EQ(camera.set_strong_light(true, 10), Outcome::kFailure);
  ASSERT_EQ(camera.set_backlight(false, 0), Outcome::kOk);
  EXPECT_EQ(camera.set_strong_light(true, 10), Outcome::kOk);
}

TEST_F(SimCamera, TfUpgradeReportsProgressAndSuccess) {
  ASSERT_EQ(camera.start_tf_upgrade(), Outcome::kOk);
  EXPECT_EQ(camera.start_tf_upgrade(), Outcome::kBusy);
  EXPECT_EQ(camera.take_photo(0, "", ""), Outcome::kBusy);
  run(camera, 10.5, events);
  EXPECT_EQ(states_of<TfUpgradeStatusEvent>(events),
            (std::vector{TfUpgradeState::kUpgrading, TfUpgradeState::kSucceeded}));
  const auto progress = events_of<MaintenanceEvent>(events);
  ASSERT_EQ(progress.size(), 11u);
  EXPECT_EQ(progress[5].state, MaintenanceState::kUpgrading);
  EXPECT_EQ(progress[5].progress, 50);
  EXPECT_EQ(progress.back().state, MaintenanceState::kSucceeded);
}

TEST(SimClock, CivilDatesAcrossLeapYearsAndBeforeTheEpoch) {
  EXPECT_EQ(civil_from_days(0).year, 1970);
  const CivilDate leap = civil_from_days(19782);  // 2024-02-29
  EXPECT_EQ(leap.year, 2024);
  EXPECT_EQ(leap.month, 2u);
  EXPECT_EQ(leap.day, 29u);
  const CivilDate before = civil_from_days(-1);
  EXPECT_EQ(before.year, 1969);
  EXPECT_EQ(before.month, 12u);
  EXPECT_EQ(before.day, 31u);
}

}  // namespace
}  // namespace k40t::sim
