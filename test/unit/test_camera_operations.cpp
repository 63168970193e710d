// ZoomTo, SdFormat, PreciseReshoot, TfUpgrade: each status state's step (sections 3.2.4.5,
// 3.2.4.7, 3.2.4.11, 3.2.4.12), goal validation with nothing built for a bad goal, and the
// precise re-shoot request built from physical units and the latest 0x000005.
#include <gtest/gtest.h>

#include <initializer_list>
#include <utility>
#include <vector>

#include "k40t_driver/operations/camera_operations.h"

namespace k40t::operations {
namespace {

namespace p = protocol;

// The phase `step_of` gives for a status frame with `field` set to each case's state.
template <class Status, class State>
void expect_phases(Step (*step_of)(const Status&), State Status::*field,
                   std::initializer_list<std::pair<State, Phase>> cases) {
  for (const auto& [state, phase] : cases) {
    Status s;
    s.*field = state;
    EXPECT_EQ(step_of(s).phase, phase) << Status::kName << " state " << static_cast<int>(state);
  }
}

// Feeds the operation a `Status` frame with `field` (which may be a member of a base the frame
// shares with others) set to each state in turn; the phase after each.
template <class Status, class Op, class Owner, class State>
std::vector<Phase> phases_after(Result<Op>& op, State Owner::*field,
                                std::initializer_list<State> states) {
  std::vector<Phase> phases;
  for (State state : states) {
    Status s;
    s.*field = state;
    op->on_status(s);
    phases.push_back(op->tracker().phase());
  }
  return phases;
}

TEST(StatusSteps, ZoomStatus) {
  expect_phases(
      zoom_step, &p::ZoomStatus::progress,
      {{p::ZoomProgress::kZooming, Phase::kRunning}, {p::ZoomProgress::kDone, Phase::kSucceeded}});
}

TEST(StatusSteps, SdFormatStatus) {
  expect_phases(sd_format_step, &p::SdFormatStatus::state,
                {{p::SdFormatState::kFormatting, Phase::kRunning},
                 {p::SdFormatState::kDone, Phase::kSucceeded},
                 {p::SdFormatState::kFailed, Phase::kFailed},
                 {p::SdFormatState::kUnavailable, Phase::kFailed}});
  p::SdFormatStatus s;
  s.state = p::SdFormatState::kUnavailable;
  EXPECT_EQ(sd_format_step(s).text, "SD card unavailable");
}

TEST(StatusSteps, PreciseReshootStatusEveryState) {
  // Section 3.2.4.7 byte 2: 0 completed, 12 precise re-shooting, 1/2/3/5 shooting, 4 stopped,
  // 6 failed, 7..11 SD card problems.
  for (int code = 0; code <= 12; ++code) {
    p::PreciseReshootStatus s;
    s.state = static_cast<p::ReshootState>(code);
    const Phase expected = code == 0                                             ? Phase::kSucceeded
                           : (code >= 1 && code <= 3) || code == 5 || code == 12 ? Phase::kRunning
                                                                                 : Phase::kFailed;
    EXPECT_EQ(reshoot_step(s).phase, expected) << "state " << code;
    EXPECT_FALSE(reshoot_step(s).text.empty());
  }
  p::PreciseReshootStatus unknown;
  unknown.state = static_cast<p::ReshootState>(40);
  EXPECT_EQ(reshoot_step(unknown).phase, Phase::kFailed);
  EXPECT_EQ(reshoot_step(unknown).text, "state 40");
}

TEST(StatusSteps, TfUpgradeStatus) {
  // Section 3.2.4.11: 0x01 upgrading, 0x02 failed, 0x00 succeeded.
  expect_phases(tf_upgrade_step, &p::TfCardUpgradeStatus::state,
                {{p::TfUpgradeState::kUpgrading, Phase::kRunning},
                 {p::TfUpgradeState::kSucceeded, Phase::kSucceeded},
                 {p::TfUpgradeState::kFailed, Phase::kFailed}});
}

TEST(ZoomTo, ValidatesTheRatioAndEndsOnDone) {
  EXPECT_FALSE(ZoomTo::create(0.5, 0, 0));
  const Result<ZoomTo> too_far = ZoomTo::create(161, 0, 0);
  ASSERT_FALSE(too_far);
  EXPECT_NE(too_far.error().find("field 'ratio'"), std::string::npos);
  Result<ZoomTo> zoom = ZoomTo::create(10, 0, 0);
  ASSERT_TRUE(zoom) << zoom.error();
  EXPECT_EQ(zoom->request().zoom_x, 10);
  EXPECT_EQ(zoom->tracker().timeout_s(), ZoomTo::kDefaultTimeoutS);
  EXPECT_FALSE(zoom->ratio_x());
  p::VisibleStatus visible;
  visible.zoom_x = 4.2;
  zoom->on_visible(visible);
  EXPECT_EQ(zoom->ratio_x().value(), 4.2);
  zoom->tracker().acknowledged(true, "ok");
  EXPECT_EQ(phases_after<p::ZoomStatus>(zoom, &p::ZoomStatus::progress,
                                        {p::ZoomProgress::kZooming, p::ZoomProgress::kDone}),
            (std::vector{Phase::kRunning, Phase::kRunning}))
      << "done, but 0x000005 still says 4.2x: its next report decides";
  visible.zoom_x = 10;
  zoom->on_visible(visible);
  EXPECT_EQ(zoom->tracker().phase(), Phase::kSucceeded);
}

// A "done" at another ratio than asked is no success (it used to be one); a goal at the current
// ratio ends when 0x000005 shows it, with no "done" frame (the document promises none for it).
TEST(ZoomTo, TheRatioReachedDecides) {
  Result<ZoomTo> clamped = ZoomTo::create(2.0, 0, 0);
  ASSERT_TRUE(clamped);
  clamped->tracker().acknowledged(true, "ok");
  p::ZoomStatus done;
  done.progress = p::ZoomProgress::kDone;
  p::VisibleStatus visible;
  visible.zoom_x = 3.5;
  clamped->on_visible(visible);
  clamped->on_status(done);
  for (int i = 0; i < ZoomTo::kReportsAfterDone; ++i) {
    EXPECT_EQ(clamped->tracker().phase(), Phase::kRunning);
    clamped->on_visible(visible);
  }
  EXPECT_EQ(clamped->tracker().phase(), Phase::kFailed);
  EXPECT_EQ(clamped->tracker().reason(),
            "zoom failed: the pod reported done at 3.5x, not the 2.0x asked for");

  Result<ZoomTo> here = ZoomTo::create(3.5, 0, 0);
  ASSERT_TRUE(here);
  here->on_visible(visible);  // already there, before the ACK: the ACK decides
  EXPECT_EQ(here->tracker().phase(), Phase::kRunning);
  here->tracker().acknowledged(true, "ok");
  EXPECT_EQ(here->tracker().phase(), Phase::kSucceeded);
  EXPECT_EQ(here->tracker().reason(), "zoom: at 3.5x");
}

TEST(SdFormat, TimeoutChoice) {
  EXPECT_EQ(SdFormat::create(0, 0)->tracker().timeout_s(), SdFormat::kDefaultTimeoutS);
  EXPECT_EQ(SdFormat::create(3, 0)->tracker().timeout_s(), 3);
  EXPECT_FALSE(SdFormat::create(-3, 0));
}

// reshoot_request itself (defaults from 0x000005, ranges): test/unit/test_reshoot_request.cpp.
TEST(PreciseReshoot, RequestFromTheArgsAndTheLatestVisibleStatus) {
  p::VisibleStatus visible;
  visible.zoom_x = 6.5;
  visible.precise_shot_focal_length_mm = 12.34;  // bytes 13-14 = 1234 (0.01 mm)
  PreciseReshootGoal goal;
  goal.args.lens = 2;
  goal.args.resolution = 0x14;  // section 3.2.4.7 byte 2: 8000*6000
  goal.args.folder = "survey";
  goal.args.name = "pole_7";
  Result<PreciseReshoot> shot = PreciseReshoot::create(goal, visible, 0);
  ASSERT_TRUE(shot) << shot.error();
  const p::PreciseReshootRequest& r = shot->request();
  EXPECT_EQ(r.lens, p::PhotoLensMode::kVisible);
  EXPECT_EQ(r.resolution, p::ReshootResolution::k8000x6000);
  EXPECT_EQ(r.zoom_x, 6.5);
  EXPECT_EQ(r.focal_length_raw, 1234);
  EXPECT_EQ(r.folder, "survey");
  EXPECT_EQ(shot->tracker().timeout_s(), PreciseReshoot::kDefaultTimeoutS);
}

TEST(PreciseReshoot, RefusesBadGoals) {
  p::VisibleStatus visible;
  PreciseReshootGoal goal;
  goal.args.resolution = 0x15;
  const Result<PreciseReshoot> no_status = PreciseReshoot::create(goal, std::nullopt, 0);
  ASSERT_FALSE(no_status);
  EXPECT_NE(no_status.error().find("0x000005"), std::string::npos);
  goal.args.zoom_ratio = 2;
  goal.args.focal_length_mm = 10;
  EXPECT_TRUE(PreciseReshoot::create(goal, std::nullopt, 0));  // nothing taken from the report
  goal.timeout_s = -1;
  const Result<PreciseReshoot> timeout = PreciseReshoot::create(goal, visible, 0);
  ASSERT_FALSE(timeout);
  EXPECT_NE(timeout.error().find("field 'timeout'"), std::string::npos);
  goal.timeout_s = 0;
  goal.args.resolution = 0x18;
  EXPECT_FALSE(PreciseReshoot::create(goal, visible, 0));
}

TEST(PreciseReshoot, EndsOnTakenOrAFailureState) {
  p::VisibleStatus visible;
  visible.zoom_x = 1;
  PreciseReshootGoal goal;
  goal.args.resolution = 0x15;
  Result<PreciseReshoot> shot = PreciseReshoot::create(goal, visible, 0);
  ASSERT_TRUE(shot);
  shot->tracker().acknowledged(true, "ok");
  EXPECT_EQ(phases_after<p::PreciseReshootStatus>(
                shot, &p::PreciseReshootStatus::state,
                {p::ReshootState::kReshooting, p::ReshootState::kSdFull}),
            (std::vector{Phase::kRunning, Phase::kFailed}));
}

TEST(TfUpgrade, ProgressOnlyFromUpgradingFrames) {
  Result<TfUpgrade> upgrade = TfUpgrade::create(0, 0);
  ASSERT_TRUE(upgrade);
  EXPECT_EQ(upgrade->tracker().timeout_s(), TfUpgrade::kDefaultTimeoutS);
  upgrade->tracker().acknowledged(true, "ok");
  p::CameraUpgradeStatus progress;
  progress.state = p::CameraUpgradeState::kRepairing;  // a calibration's
  progress.progress_percent = 70;
  upgrade->on_progress(progress);
  EXPECT_EQ(upgrade->progress_percent(), -1);
  progress.state = p::CameraUpgradeState::kUpgrading;
  progress.progress_percent = 30;
  upgrade->on_progress(progress);
  EXPECT_EQ(upgrade->progress_percent(), 30);
  p::TfCardUpgradeStatus status;
  status.state = p::TfUpgradeState::kSucceeded;
  upgrade->on_status(status);
  EXPECT_EQ(upgrade->tracker().phase(), Phase::kSucceeded);
}

}  // namespace
}  // namespace k40t::operations
