// SettingWrites (driver/setting_writes.h), the read-back's rules on a small configuration of its
// own: a setting written during a read keeps its written value, whatever the read got; a
// write-only setting that was written is sent again after a read-back, a readable one is not.
#include <gtest/gtest.h>

#include "k40t_driver/driver/setting_writes.h"

namespace k40t::driver {
namespace {

struct TestConfig {
  int palette = 0;  // readable (0x010100)
  int zoom = 0;     // readable (0x000003)
  int ranging = 0;  // write-only
};

using Binding = BasicSettingBinding<TestConfig>;

Binding binding(const std::string& name, int TestConfig::*member, protocol::MessageId read_from) {
  Binding b;
  b.name = name;
  b.copy = [member](TestConfig& to, const TestConfig& from) { to.*member = from.*member; };
  b.read_from = read_from;
  return b;
}

const std::vector<Binding>& table() {
  static const std::vector<Binding> bindings = {binding("palette", &TestConfig::palette, 0x010100),
                                                binding("zoom", &TestConfig::zoom, 0x000003),
                                                binding("ranging", &TestConfig::ranging, 0)};
  return bindings;
}

TEST(SettingWrites, WrittenDuringTheReadKeepsTheWrittenValue) {
  SettingWrites writes;
  writes.read_started();
  writes.written("palette");
  const TestConfig written{7, 3, 1};
  TestConfig read{2, 5, 0};
  writes.keep_written(table(), read, written);
  EXPECT_EQ(read.palette, 7);  // written during the read: the written value
  EXPECT_EQ(read.zoom, 5);     // not written: what the read got
  EXPECT_EQ(read.ranging, 0);
}

TEST(SettingWrites, WrittenBeforeTheReadTakesTheReadValue) {
  SettingWrites writes;
  writes.written("palette");
  writes.read_started();
  TestConfig read{2, 5, 0};
  writes.keep_written(table(), read, TestConfig{7, 3, 1});
  EXPECT_EQ(read.palette, 2);
  EXPECT_EQ(read.zoom, 5);
}

TEST(SettingWrites, ResendsOnlyWriteOnlySettingsThatWereWritten) {
  SettingWrites writes;
  EXPECT_TRUE(writes.to_resend(table()).empty());
  writes.written("palette");
  EXPECT_TRUE(writes.to_resend(table()).empty());  // readable: the read-back has it
  writes.written("ranging");
  writes.read_started();  // a later read does not forget what was ever written
  EXPECT_EQ(writes.to_resend(table()), std::vector<const Binding*>{&table()[2]});  // ranging
}

}  // namespace
}  // namespace k40t::driver
