// changes_to_send() (driver/setting_binding.h), the rule a reconfigure follows, on a small
// configuration of its own: what is sent, that a value the pod reported outside the cfg range is
// left alone by a change of another setting, and that switching a setting off goes before
// switching another on (3.2.3.9/3.2.3.10 note).
#include <gtest/gtest.h>

#include "k40t_driver/driver/setting_binding.h"

namespace k40t::driver {
namespace {

struct TestConfig {
  int palette = 1;     // cfg range 1..20
  int resolution = 1;  // cfg range 1..21
  bool backlight = false;
  bool strong_light = false;
};

using Binding = BasicSettingBinding<TestConfig>;

Binding int_binding(const std::string& name, int TestConfig::*member) {
  Binding b;
  b.name = name;
  b.differs = [member](const TestConfig& a, const TestConfig& c) { return a.*member != c.*member; };
  b.copy = [member](TestConfig& to, const TestConfig& from) { to.*member = from.*member; };
  return b;
}

Binding switch_binding(const std::string& name, bool TestConfig::*member) {
  Binding b;
  b.name = name;
  b.differs = [member](const TestConfig& a, const TestConfig& c) { return a.*member != c.*member; };
  b.copy = [member](TestConfig& to, const TestConfig& from) { to.*member = from.*member; };
  b.switches_off = [member](const TestConfig& next, const TestConfig& current) {
    return current.*member && !(next.*member);
  };
  return b;
}

const std::vector<Binding>& table() {
  static const std::vector<Binding> bindings = {
      int_binding("palette", &TestConfig::palette),
      int_binding("resolution", &TestConfig::resolution),
      switch_binding("strong_light", &TestConfig::strong_light),
      switch_binding("backlight", &TestConfig::backlight),
  };
  return bindings;
}

std::vector<std::string> names(const std::vector<const Binding*>& bindings) {
  std::vector<std::string> out;
  for (const Binding* b : bindings) out.push_back(b->name);
  return out;
}

TEST(SettingChanges, NothingChangedSendsNothing) {
  TestConfig current;
  TestConfig next = current;
  EXPECT_TRUE(changes_to_send(table(), next, current).empty());
}

TEST(SettingChanges, EachChangedSettingIsSentOnceInTableOrder) {
  TestConfig current;
  TestConfig next = current;
  next.resolution = 5;
  next.palette = 3;
  EXPECT_EQ(names(changes_to_send(table(), next, current)),
            (std::vector<std::string>{"palette", "resolution"}));
  EXPECT_EQ(next.palette, 3);
  EXPECT_EQ(next.resolution, 5);
}

TEST(SettingChanges, AValueThePodReportedOutsideTheRangeStaysBesideAnotherChange) {
  TestConfig current;
  current.resolution = 22;  // the pod reported a value above the cfg's 21
  TestConfig next = current;
  next.palette = 4;  // the user changes the palette only: nothing clamps the resolution
  EXPECT_EQ(names(changes_to_send(table(), next, current)), (std::vector<std::string>{"palette"}));
  EXPECT_EQ(next.resolution, 22);
}

TEST(SettingChanges, SwitchingOffGoesFirst) {
  TestConfig current;
  current.backlight = true;  // backlight on, strong light off ...
  TestConfig next = current;
  next.backlight = false;  // ... swapped: backlight must be off before strong light goes on
  next.strong_light = true;
  next.palette = 2;
  EXPECT_EQ(names(changes_to_send(table(), next, current)),
            (std::vector<std::string>{"backlight", "palette", "strong_light"}));
}

}  // namespace
}  // namespace k40t::driver
