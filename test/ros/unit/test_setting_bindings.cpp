// The settings bindings' rules that keep dynamic_reconfigure honest (issues 10, 24): a requested
// value outside the cfg range is named with the range (it is refused, not clamped), a value the pod
// reported outside a range is left alone, and switching strong-light suppression or backlight
// compensation off is recognised so that it is sent before the other one is switched on
// (3.2.3.9/3.2.3.10 note).
#include <gtest/gtest.h>

#include "k40t_driver/ros/settings_sync.h"

namespace k40t::driver {
namespace {

const SettingBinding& binding(const std::string& name) {
  const SettingBinding* b = find_binding(name);
  EXPECT_NE(b, nullptr) << name;
  return *b;
}

TEST(SettingBindings, AChangedValueOutsideTheCfgRangeIsNamedWithTheRange) {
  const Config current = Config::__getDefault__();
  Config next = current;
  next.palette = 99;  // cfg range 1..20 (issue 24: was clamped to 20 and sent)
  EXPECT_EQ(outside_cfg_range(next, current, parameters_of(binding("palette"))),
            "palette 99 is outside 1..20");
  next.palette = 20;
  EXPECT_EQ(outside_cfg_range(next, current, parameters_of(binding("palette"))), "");
}

TEST(SettingBindings, EachParameterOutsideItsRangeIsNamedDoublesToo) {
  const Config current = Config::__getDefault__();
  Config next = current;
  next.timelapse_interval = 100;  // 5..60
  next.burst_count = 2;           // 3..5
  EXPECT_EQ(outside_cfg_range(next, current, parameters_of(binding("photo_mode"))),
            "timelapse_interval 100 is outside 5..60; burst_count 2 is outside 3..5");
  next = current;
  next.high_alarm_degC = 600.5;  // -100..500
  const std::string text = outside_cfg_range(next, current, {"high_alarm_degC"});
  EXPECT_EQ(text, "high_alarm_degC 600.5 is outside -100..500");
}

TEST(SettingBindings, AValueThePodReportedOutsideTheRangeIsNotTheRequestsFault) {
  Config pod = Config::__getDefault__();
  pod.photo_resolution = 0x16;  // 5160x3870: reported by 0x010200, not settable by 0x000202
  Config next = pod;            // unchanged: not checked
  EXPECT_EQ(outside_cfg_range(next, pod, parameters_of(binding("photo_resolution"))), "");
  next.photo_resolution = 0x15;  // back inside
  EXPECT_EQ(outside_cfg_range(next, pod, parameters_of(binding("photo_resolution"))), "");
}

TEST(SettingBindings, TheRefusalParameterBelongsToNoBinding) {
  for (const SettingBinding& b : setting_bindings()) {
    for (const std::string& name : parameters_of(b)) EXPECT_NE(name, kLastRefusalParameter);
  }
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
