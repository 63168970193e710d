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

}  // namespace
}  // namespace k40t::driver
