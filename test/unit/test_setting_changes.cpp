// changes_to_send() (driver/setting_binding.h), the rule a reconfigure follows, on a small
// configuration of its own: what is sent, what is only dynamic_reconfigure's clamping of a value
// the pod reported outside the cfg range (not sent, the pod's value kept), and that switching a
// setting off goes before switching another on (3.2.3.9/3.2.3.10 note).
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

// A binding of one int field, clamped into [lo, hi] as dynamic_reconfigure does.
Binding range_binding(const std::string& name, int TestConfig::*member, int lo, int hi) {
  Binding b;
  b.name = name;
  b.differs = [member](const TestConfig& a, const TestConfig& c) { return a.*member != c.*member; };
  b.copy = [member](TestConfig& to, const TestConfig& from) { to.*member = from.*member; };
  b.only_clamped = [member, lo, hi](const TestConfig& next, const TestConfig& current) {
    return (current.*member < lo && next.*member == lo) ||
           (current.*member > hi && next.*member == hi);
  };
  return b;
}

Binding switch_binding(const std::string& name, bool TestConfig::*member) {
  Binding b;
  b.name = name;
  b.differs = [member](const TestConfig& a, const TestConfig& c) { return a.*member != c.*member; };
  b.copy = [member](TestConfig& to, const TestConfig& from) { to.*member = from.*member; };
  b.only_clamped = [](const TestConfig&, const TestConfig&) { return false; };
  b.switches_off = [member](const TestConfig& next, const TestConfig& current) {
    return current.*member && !(next.*member);
  };
  return b;
}

const std::vector<Binding>& table() {
  static const std::vector<Binding> bindings = {
      range_binding("palette", &TestConfig::palette, 1, 20),
      range_binding("resolution", &TestConfig::resolution, 1, 21),
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

TEST(SettingChanges, AClampBesideARealChangeIsNotSentAndKeepsThePodsValue) {
  TestConfig current;
  current.resolution = 22;  // the pod reported a value above the cfg's 21
  TestConfig next = current;
  next.resolution = 21;  // dynamic_reconfigure clamped it
  next.palette = 4;      // while the user changed the palette
  EXPECT_EQ(names(changes_to_send(table(), next, current)), (std::vector<std::string>{"palette"}));
  EXPECT_EQ(next.resolution, 22);  // what the server publishes: the pod's value
}

TEST(SettingChanges, AClampAloneIsTheUserChoosingTheBound) {
  TestConfig current;
  current.resolution = 22;
  TestConfig next = current;
  next.resolution = 21;
  EXPECT_EQ(names(changes_to_send(table(), next, current)),
            (std::vector<std::string>{"resolution"}));
  EXPECT_EQ(next.resolution, 21);
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
