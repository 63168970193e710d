// 3.5.5's angles in the frame of 3.5.1 (docs/psdk.md P28): with `gimbal_angle_layout:
// dji_headers` (the default) an angle command names the NED attitude and the bridge drives the
// pod's joints to joint = NED - (attitude - joint); with `document`, the joint angles as given.
// 3.5.6 is joint angles and return head the joints' centre in either layout. Expected pod calls
// are worked out by hand in the comments (REP 103 radians: pitch down, yaw left positive).
#include "k40t_driver/skyport/gimbal_frame.h"
#include "skyport_bridge_rig.h"

namespace k40t::driver::skyport {
namespace {

using namespace psdk;
using namespace bridge_testing;

constexpr double kRadPerDeg = M_PI / 180.0;

PodSnapshot pose(double joint_pitch_deg, double joint_yaw_deg, double attitude_pitch_deg,
                 double attitude_yaw_deg) {
  // DJI signs in, REP 103 radians stored: both angles change sign.
  PodSnapshot s;
  s.have_joints = s.have_attitude = true;
  s.pitch_rad = -joint_pitch_deg * kRadPerDeg;
  s.yaw_rad = -joint_yaw_deg * kRadPerDeg;
  s.attitude_pitch_rad = -attitude_pitch_deg * kRadPerDeg;
  s.attitude_yaw_rad = -attitude_yaw_deg * kRadPerDeg;
  return s;
}

TEST(GimbalFrame, TheHeadingIsTakenOffTheYaw) {
  // Joint yaw 20 right, attitude yaw 110: the aircraft heads 90. NED yaw 100 -> joint 10.
  const auto joint = joint_target_from_ned({-30, 100}, pose(-30, 20, -30, 110));
  ASSERT_TRUE(joint);
  EXPECT_NEAR(joint->pitch_deg, -30, 1e-9);
  EXPECT_NEAR(joint->yaw_deg, 10, 1e-9);
}

TEST(GimbalFrame, TheYawWrapsAcrossTheBack) {
  // Heading 170 (joint 0, attitude 170); NED -170 is 20 degrees right of the nose: joint +20,
  // not -340.
  const auto joint = joint_target_from_ned({0, -170}, pose(0, 0, 0, 170));
  ASSERT_TRUE(joint);
  EXPECT_NEAR(joint->yaw_deg, 20, 1e-9);
  // Heading -170, NED 170: 20 degrees left, joint -20.
  EXPECT_NEAR(joint_target_from_ned({0, 170}, pose(0, 0, 0, -170))->yaw_deg, -20, 1e-9);
}

TEST(GimbalFrame, ThePitchOffsetIsTakenOffThePitch) {
  // The attitude reads 5 degrees above the joint (the aircraft noses up 5): NED -30 -> joint -35.
  const auto joint = joint_target_from_ned({-30, 0}, pose(-10, 0, -5, 0));
  ASSERT_TRUE(joint);
  EXPECT_NEAR(joint->pitch_deg, -35, 1e-9);
}

TEST(GimbalFrame, NoTargetWithoutTheAttitudeOrTheJoints) {
  PodSnapshot s = pose(0, 0, 0, 90);
  s.have_attitude = false;
  EXPECT_FALSE(joint_target_from_ned({0, 0}, s));
  s = pose(0, 0, 0, 90);
  s.have_joints = false;
  EXPECT_FALSE(joint_target_from_ned({0, 0}, s));
}

Rig rig_with_angles(PsdkLayout layout) {
  return Rig(kCredentials, BridgeOptions{}.photo_storing_s,
             [layout](BridgeOptions& o) { o.gimbal_angle_layout = layout; });
}

// 3.5.5 sent; the ACK's code (0xFF: no ACK).
int angle_code(Rig& rig, double pitch_deg, double yaw_deg) {
  ControlGimbalAngle c;
  c.pitch_deg = pitch_deg;
  c.yaw_deg = yaw_deg;
  AckResult raw;
  rig.ask(c, &raw);
  return raw.received ? raw.code() : 0xFF;
}

// 3.5.1's angles (DJI signs).
GimbalAngles state_angles(Rig& rig) {
  const Result<GimbalStateAck> state = rig.ask(GetGimbalState{});
  EXPECT_TRUE(state) << state.error();
  return state ? state->angles : GimbalAngles{};
}

TEST(SkyportGimbalFrame, NedIsTheDefault) {
  EXPECT_EQ(BridgeOptions{}.gimbal_angle_layout, PsdkLayout::kDjiHeaders);
}

TEST(SkyportGimbalFrame, NedAnglesDriveTheJointsAndReadBack) {
  // The fake pod: joints pitch -30, yaw 20 right; attitude pitch -30, yaw 110 (heading 90).
  Rig rig = rig_with_angles(PsdkLayout::kDjiHeaders);
  EXPECT_EQ(angle_code(rig, -30, 20), 0x00);
  // NED yaw 20 - heading 90 = joint yaw -70 (left): REP 103 +70 deg = 1.2217 rad; pitch -30
  // (offset 0): 0.5236 rad down.
  EXPECT_TRUE(has_call(rig.pod, "angle 0.5236 1.2217"));
  // The pod there (joint -70, heading 90) reads NED 20: what was set.
  rig.pod.set_gimbal(30 * kRadPerDeg, 70 * kRadPerDeg, 30 * kRadPerDeg, -20 * kRadPerDeg);
  const GimbalAngles state = state_angles(rig);
  EXPECT_NEAR(state.pitch_deg, -30, 0.1);
  EXPECT_NEAR(state.yaw_deg, 20, 0.1);
}

TEST(SkyportGimbalFrame, JointAnglesAndReturnHeadIgnoreTheHeading) {
  Rig rig = rig_with_angles(PsdkLayout::kDjiHeaders);
  ControlGimbalJointAngle joint;
  joint.angles.pitch_deg = -30;
  joint.angles.yaw_deg = 20;
  AckResult raw;
  ASSERT_TRUE(rig.ask(joint, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "angle 0.5236 -0.3491"));  // 30 down, 20 right
  ASSERT_TRUE(rig.ask(GimbalReturnHead{}, &raw));
  EXPECT_EQ(raw.code(), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "center"));
}

TEST(SkyportGimbalFrame, NedAnglesWithoutAnAttitudeAreRefused) {
  Rig rig = rig_with_angles(PsdkLayout::kDjiHeaders);
  rig.pod.set_gimbal(0, 0, std::nullopt, std::nullopt);
  EXPECT_EQ(angle_code(rig, -30, 20), 0x01);
  EXPECT_TRUE(rig.pod.calls().empty());  // nothing sent to the pod
}

TEST(SkyportGimbalFrame, JointLayoutDrivesTheJointsAsGiven) {
  Rig rig = rig_with_angles(PsdkLayout::kDocument);
  EXPECT_EQ(angle_code(rig, -30, 20), 0x00);
  EXPECT_TRUE(has_call(rig.pod, "angle 0.5236 -0.3491"));
  EXPECT_NEAR(state_angles(rig).yaw_deg, 20, 0.1);  // the joint, not the attitude's 110
}

// skyport_sim's own gimbal check (set the angle, poll the state, return head, poll again) passes
// with the bridge and the adapter agreeing on either layout. The adapter's flight heads north
// while it climbs (these checks end well within its 10 s), so the pod heads north too.
TEST(SkyportGimbalFrame, TheAdaptersCheckPassesInEitherLayout) {
  for (const auto& [layout, reading] :
       {std::pair{PsdkLayout::kDjiHeaders, psdk::sim::PayloadReading::kDjiHeaders},
        std::pair{PsdkLayout::kDocument, psdk::sim::PayloadReading::kDocument}}) {
    Rig rig(
        kCredentials, BridgeOptions{}.photo_storing_s,
        [layout = layout](BridgeOptions& o) {
          o.gimbal_angle_layout = o.gimbal_mode_layout = layout;
        },
        reading);
    rig.pod.set_gimbal(0, 0, 0, 0);
    const psdk::sim::CheckReport report = rig.adapter->check_gimbal();
    EXPECT_TRUE(report.passed()) << to_string(layout) << ": " << report.summary();
  }
}

// A pod whose attitude says the aircraft heads east while the adapter's flies north: the NED
// state is 90 degrees off what the adapter set, and its check says so (it can fail).
TEST(SkyportGimbalFrame, TheAdaptersCheckFailsOnAHeadingItsFlightDoesNotHave) {
  Rig rig = rig_with_angles(PsdkLayout::kDjiHeaders);
  // Joints 0, attitude yaw 90 right (REP 103: -90 deg).
  rig.pod.set_gimbal(0, 0, 0, -M_PI / 2);
  const psdk::sim::CheckReport report = rig.adapter->check_gimbal();
  EXPECT_FALSE(report.passed());
  EXPECT_NE(report.summary().find("FAIL gimbal_returns_to_centre"), std::string::npos)
      << report.summary();
}

}  // namespace
}  // namespace k40t::driver::skyport
