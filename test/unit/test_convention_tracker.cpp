// The driver's view of the open readings (driver/convention_tracker.h) and the `conventions`
// diagnostic (driver/convention_health.h), fed by hand with decoded frames and explicit times.
#include <gtest/gtest.h>

#include "k40t_driver/driver/convention_health.h"
#include "k40t_driver/driver/convention_tracker.h"

namespace k40t::driver {
namespace {

namespace p = protocol;

p::GimbalAttitude at(double joint_yaw, double joint_pitch = 0, double yaw_rate = 0) {
  p::GimbalAttitude m;
  m.joint_yaw_deg = m.yaw_deg = joint_yaw;
  m.joint_pitch_deg = m.pitch_deg = joint_pitch;
  m.yaw_rate_deg_s = yaw_rate;
  return m;
}

ConventionStatus reading(const ConventionTracker& t, const std::string& name) {
  for (const ConventionStatus& s : t.report())
    if (s.name == name) return s;
  return {};
}

TEST(ConventionTracker, SourcesAreDefaultParameterOrDetected) {
  p::CodecOptions codec;
  codec.conventions.pitch_sign = p::PitchSign::kDown;
  ConventionTracker t(p::CrcCoverage::kAuto, codec, {"pitch_sign"});
  EXPECT_EQ(reading(t, "yaw_sign").source, "default");
  EXPECT_EQ(reading(t, "pitch_sign").source, "parameter");
  EXPECT_EQ(reading(t, "pitch_sign").value, "down");
  t.observe_crc_coverage(p::CrcCoverage::kWholeFrame);
  EXPECT_EQ(reading(t, "crc_coverage").value, "whole_frame");
  EXPECT_EQ(reading(t, "crc_coverage").source, "detected from the first frames' checksums");
  // 350 deg as a uint16 heading reads -305.36 as int16: auto locks onto heading.
  t.observe_attitude(at(-305.36), 0.0);
  EXPECT_EQ(t.yaw_range(), p::YawRange::kHeading);
  EXPECT_NE(reading(t, "yaw_range").source.find("detected from 0x000002 yaw -305.36 deg"),
            std::string::npos);
  EXPECT_NEAR(t.applied(at(-305.36)).joint_yaw_deg, -10.0, 1e-9);
  EXPECT_FALSE(t.contradicted());
  EXPECT_EQ(conventions_health(t.report()).level, HealthLevel::kOk);
}

TEST(ConventionTracker, AMoveCountedTheOtherWayContradictsTheSign) {
  ConventionTracker t(p::CrcCoverage::kAuto, p::CodecOptions{}, {});
  t.observe_attitude(at(0), 0.0);
  p::GimbalControlRequest left;
  left.yaw = p::GimbalYawDirection::kLeft;
  t.observe_command(left, 0.1);
  t.observe_attitude(at(1.5), 0.2);  // not far enough to tell
  EXPECT_FALSE(t.contradicted());
  t.observe_attitude(at(2.5), 0.3);  // left, counted positive: the pod's yaw is left-positive
  ASSERT_TRUE(t.contradicted());
  const std::string why = reading(t, "yaw_sign").contradiction;
  EXPECT_EQ(why,
            "0x000010 yaw left but 0x000002 counts the yaw as 2.50 deg (from 0.00 deg) under "
            "yaw_sign: right; the pod's yaw is left-positive (yaw_sign: left)");
  const HealthCheck health = conventions_health(t.report());
  EXPECT_EQ(health.level, HealthLevel::kWarn);
  EXPECT_NE(health.summary.find("yaw_sign"), std::string::npos);
  ASSERT_NE(health.value("yaw_sign contradicted"), nullptr);
}

TEST(ConventionTracker, AnAngleCommandCountsOnceSettled) {
  ConventionTracker t(p::CrcCoverage::kAuto, p::CodecOptions{}, {});
  t.observe_attitude(at(-30), 0.0);  // already at -30: a move to +30 passes through nothing
  p::GimbalAngleRequest right;
  right.yaw_deg = 30;
  right.pitch_move = false;
  t.observe_command(right, 0.0);
  t.observe_attitude(at(-30), 0.5);  // not started yet: too early to count
  EXPECT_FALSE(t.contradicted());
  t.observe_attitude(at(0, 0, 20), 2.0);  // moving
  t.observe_attitude(at(30), 3.5);        // settled at the target: agrees
  EXPECT_FALSE(t.contradicted());
  p::GimbalAngleRequest left = right;
  left.yaw_deg = -20;
  t.observe_command(left, 4.0);
  t.observe_attitude(at(20), 6.0);  // settled at +20 for a target of 20 left
  EXPECT_NE(reading(t, "yaw_sign").contradiction.find("0x000012 yaw 20.00 deg left"),
            std::string::npos);
}

TEST(ConventionTracker, CalibrationEndFromWhat0x000008Does) {
  p::CodecOptions status;
  status.conventions.calibration_end = p::CalibrationEnd::kStatus;
  ConventionTracker wrong(p::CrcCoverage::kAuto, status, {"calibration_end"});
  wrong.observe_calibration_acked(10.0);
  wrong.observe_attitude(at(0), 12.0);
  EXPECT_FALSE(wrong.contradicted());
  wrong.observe_attitude(at(0), 12.6);  // 2.6 s and no "repairing"
  EXPECT_NE(reading(wrong, "calibration_end").contradiction.find("no 0x000008 'repairing'"),
            std::string::npos);

  ConventionTracker detecting(p::CrcCoverage::kAuto, p::CodecOptions{}, {});
  detecting.observe_calibration_acked(10.0);
  p::CameraUpgradeStatus repairing;
  repairing.state = p::CameraUpgradeState::kRepairing;
  detecting.observe_upgrade_status(repairing, 10.4);
  EXPECT_EQ(reading(detecting, "calibration_end").source,
            "detected from 0x000008 'repairing' 0.4 s after a calibration's OK ACK (the pod's "
            "reading: status)");
}

}  // namespace
}  // namespace k40t::driver
