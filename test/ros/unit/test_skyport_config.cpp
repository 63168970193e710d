// read_skyport_config against parameters on the rostest's master: bad values are errors naming the
// parameter, and the key file is read (its first line, trimmed).
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <ros/ros.h>

#include "k40t_driver/ros/skyport/skyport_config.h"

namespace k40t::driver::skyport {
namespace {

class SkyportConfigTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    if (!ros::isInitialized()) {
      int argc = 0;
      ros::init(argc, nullptr, "skyport_config_test", ros::init_options::AnonymousName);
    }
  }
  void SetUp() override {
    nh_ = ros::NodeHandle(
        "skyport_config_test_" +
        std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    nh_.setParam("device", "pty:///tmp/skyport_config_test");
    nh_.setParam("app_key", "0123456789abcdef");
  }
  std::string error() const {
    Result<SkyportConfig> c = read_skyport_config(nh_);
    return c ? std::string() : c.error();
  }
  // The parameters are refused with an error that mentions `part`.
  ::testing::AssertionResult error_mentions(const std::string& part) const {
    const std::string e = error();
    if (e.find(part) != std::string::npos) return ::testing::AssertionSuccess();
    return ::testing::AssertionFailure() << "error '" << e << "' does not mention '" << part << "'";
  }
  ros::NodeHandle nh_;
};

TEST_F(SkyportConfigTest, DefaultsAreReadWithDeviceAndKey) {
  Result<SkyportConfig> c = read_skyport_config(nh_);
  ASSERT_TRUE(c) << c.error();
  EXPECT_EQ(c->device, "pty:///tmp/skyport_config_test");
  EXPECT_EQ(c->credentials.app_key, "0123456789abcdef");
  EXPECT_EQ(c->bridge.app_key, "0123456789abcdef");
  EXPECT_EQ(c->feed_fix, "raw_gps");
  EXPECT_DOUBLE_EQ(c->bridge.photo_storing_s, 2.0);
}

TEST_F(SkyportConfigTest, AMissingDeviceOrKeyIsNamed) {
  nh_.deleteParam("device");
  EXPECT_TRUE(error_mentions("~device"));
  nh_.setParam("device", "pty:///tmp/x");
  nh_.deleteParam("app_key");
  EXPECT_TRUE(error_mentions("app key"));
}

TEST_F(SkyportConfigTest, AWrongTypeIsAnErrorNotTheDefault) {
  nh_.setParam("feed_pod", "yes please");  // a string where a bool belongs
  EXPECT_TRUE(error_mentions("feed_pod"));
  EXPECT_TRUE(error_mentions("wrong type"));
}

TEST_F(SkyportConfigTest, OutOfRangeValuesNameTheParameterAndTheRange) {
  nh_.setParam("photo_storing_time", 61.0);
  EXPECT_TRUE(error_mentions("photo_storing_time"));
  EXPECT_TRUE(error_mentions("0..60"));
  nh_.setParam("photo_storing_time", 2.0);
  nh_.setParam("ack_timeout", 0.0);
  EXPECT_TRUE(error_mentions("ack_timeout"));
  nh_.setParam("ack_timeout", 1.0);
  nh_.setParam("feed_fix", "glonass");
  EXPECT_TRUE(error_mentions("feed_fix"));
  EXPECT_TRUE(error_mentions("glonass"));
}

TEST_F(SkyportConfigTest, ProductInformationDefaultsToTheAppNameAndId) {
  nh_.setParam("app_name", "MyApp");
  nh_.setParam("app_id", "123456");
  Result<SkyportConfig> c = read_skyport_config(nh_);
  ASSERT_TRUE(c) << c.error();
  EXPECT_EQ(c->bridge.product_name, "MyApp");
  EXPECT_EQ(c->bridge.product_id, "123456");
  nh_.setParam("product_id", "0123456789abcdefg");  // 17 bytes: 3.1.4 holds 15 + NUL
  EXPECT_TRUE(error_mentions("product_id"));
}

TEST_F(SkyportConfigTest, VersionsAndLayoutsAreParsedOrNamed) {
  nh_.setParam("firmware_version", "2.1.0.7");
  nh_.setParam("sd_card_layout", "document");
  Result<SkyportConfig> c = read_skyport_config(nh_);
  ASSERT_TRUE(c) << c.error();
  EXPECT_EQ(c->bridge.firmware.major, 2);
  EXPECT_EQ(c->bridge.firmware.debug, 7);
  EXPECT_EQ(c->bridge.sd_card_layout, psdk::PsdkLayout::kDocument);
  EXPECT_EQ(c->bridge.gimbal_mode_layout, psdk::PsdkLayout::kDjiHeaders);  // the default
  nh_.setParam("firmware_version", "2.1.256.0");
  EXPECT_TRUE(error_mentions("firmware_version"));
  nh_.setParam("firmware_version", "2.1.0.7");
  nh_.setParam("interval_layout", "wide");
  EXPECT_TRUE(error_mentions("interval_layout"));
  EXPECT_TRUE(error_mentions("dji_headers or document"));
}

TEST_F(SkyportConfigTest, TheKeyFileGivesItsFirstLineTrimmed) {
  const std::string path = "/tmp/skyport_config_test_key_" + std::to_string(::getpid());
  { std::ofstream(path) << "fedcba9876543210  \nsecond line\n"; }
  nh_.setParam("app_key_file", path);
  Result<SkyportConfig> c = read_skyport_config(nh_);
  std::remove(path.c_str());
  ASSERT_TRUE(c) << c.error();
  EXPECT_EQ(c->credentials.app_key, "fedcba9876543210");
  nh_.setParam("app_key_file", path);  // now gone
  EXPECT_TRUE(error_mentions("app_key_file: cannot read"));
}

}  // namespace
}  // namespace k40t::driver::skyport
