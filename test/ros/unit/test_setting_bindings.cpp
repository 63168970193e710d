// The settings bindings' rules that keep dynamic_reconfigure honest (issue 10): a value the pod
// reported outside the cfg range and then clamped by dynamic_reconfigure is recognised as such,
// and switching strong-light suppression or backlight compensation off is recognised so that it
// is sent before the other one is switched on (3.2.3.9/3.2.3.10 note).
#include <gtest/gtest.h>

#include "k40t_driver/ros/settings_sync.h"

namespace k40t::driver {
namespace {

const SettingBinding& binding(const std::string& name) {
  const SettingBinding* b = find_binding(name);
  EXPECT_NE(b, nullptr) << name;
  return *b;
}

TEST(SettingBindings, APodValueOutsideTheRangeClampedToItsBoundIsOnlyClamped) {
  Config pod = Config::__getDefault__();
  pod.photo_resolution = 0x16;  // 5160x3870: reported by 0x010200, not settable by 0x000202
  pod.white_balance = 0;        // below the cfg's 1
  Config clamped = pod;
  clamped.photo_resolution = Config::__getMax__().photo_resolution;  // 0x15
  clamped.white_balance = Config::__getMin__().white_balance;        // 1
  EXPECT_TRUE(binding("photo_resolution").differs(clamped, pod));
  EXPECT_TRUE(binding("photo_resolution").only_clamped(clamped, pod));
  EXPECT_TRUE(binding("white_balance").only_clamped(clamped, pod));
}

TEST(SettingBindings, AChangeWithinTheRangeIsARealChange) {
  Config pod = Config::__getDefault__();
  pod.photo_resolution = 0x15;
  Config next = pod;
  next.photo_resolution = 0x14;
  EXPECT_FALSE(binding("photo_resolution").only_clamped(next, pod));
  pod.photo_resolution = 0x16;  // out of range, but moved to the far bound: not a clamp
  EXPECT_FALSE(binding("photo_resolution").only_clamped(next, pod));
}

TEST(SettingBindings, SwitchingStrongLightOrBacklightOffIsRecognised) {
  Config backlight_on = Config::__getDefault__();
  backlight_on.backlight_compensation = true;
  backlight_on.strong_light_suppression = false;
  Config strong_on = backlight_on;
  strong_on.backlight_compensation = false;
  strong_on.strong_light_suppression = true;
  ASSERT_TRUE(binding("backlight_compensation").switches_off);
  ASSERT_TRUE(binding("strong_light_suppression").switches_off);
  EXPECT_TRUE(binding("backlight_compensation").switches_off(strong_on, backlight_on));
  EXPECT_FALSE(binding("strong_light_suppression").switches_off(strong_on, backlight_on));
  EXPECT_TRUE(binding("strong_light_suppression").switches_off(backlight_on, strong_on));
  EXPECT_FALSE(binding("palette").switches_off);
}

// 0x000001 byte 4 (section 3.1.1.1): 0 off, 1 stabilising, 2 failed, 3 feature lost. Only 1 is
// "on"; 2 and 3 used to read back as on.
TEST(SettingBindings, StabilisationIsOnOnlyWhileStabilising) {
  const SettingBinding& stabilisation = binding("stabilisation");
  ASSERT_TRUE(stabilisation.read_back);
  protocol::GimbalStatus gimbal;
  const SettingReports reports{nullptr, nullptr, nullptr, &gimbal};
  const std::pair<protocol::GimbalStabilisationState, bool> cases[] = {
      {protocol::GimbalStabilisationState::kOff, false},
      {protocol::GimbalStabilisationState::kStabilising, true},
      {protocol::GimbalStabilisationState::kFailed, false},
      {protocol::GimbalStabilisationState::kFeatureLost, false}};
  for (const auto& [state, on] : cases) {
    gimbal.stabilisation = state;
    Config config = Config::__getDefault__();
    config.stabilisation = !on;
    stabilisation.read_back(config, reports);
    EXPECT_EQ(config.stabilisation, on) << "state " << static_cast<int>(state);
  }
}

// One default dial speed (docs/protocol/gimbal_laser_sbus.md, 0x000017): the message struct's, the
// reconfigure parameters' (wire units, deg/s x5) and the simulated pod's were 6, 10 and 20 deg/s.
TEST(SettingBindings, TheDialSpeedHasOneDefault) {
  using Speed = protocol::GimbalDialSpeedRequest;
  const Config defaults = Config::__getDefault__();
  EXPECT_DOUBLE_EQ(defaults.pitch_dial_speed / Speed::kWirePerDegS, Speed::kDefaultDegS);
  EXPECT_DOUBLE_EQ(defaults.yaw_dial_speed / Speed::kWirePerDegS, Speed::kDefaultDegS);
  EXPECT_DOUBLE_EQ(Speed{}.pitch_speed_deg_s, Speed::kDefaultDegS);
  EXPECT_DOUBLE_EQ(Speed{}.yaw_speed_deg_s, Speed::kDefaultDegS);
}

}  // namespace
}  // namespace k40t::driver
