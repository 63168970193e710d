// The table of the document's open readings (protocol/conventions.h): every name parses every
// one of its values and prints it back, defaults are the struct's, bad text is refused by name.
#include <gtest/gtest.h>

#include <cctype>
#include <set>
#include <string>

#include "k40t_driver/protocol/conventions.h"

namespace k40t::protocol {
namespace {

struct AllReadings {
  CrcCoverage crc_coverage = CrcCoverage::kAuto;
  CodecOptions codec;
  ConventionRefs refs() { return {crc_coverage, codec}; }
  ConstConventionRefs view() const { return {crc_coverage, codec}; }
};

TEST(ConventionsTable, NamesAreUniqueSnakeCaseAndDefaultsMatchTheStructs) {
  AllReadings defaults;
  std::set<std::string> names;
  for (const ConventionInfo& info : convention_table()) {
    EXPECT_TRUE(names.insert(info.name).second) << info.name;
    for (const char c : std::string(info.name))
      EXPECT_TRUE(c == '_' || std::islower(c) || std::isdigit(c)) << info.name;
    EXPECT_EQ(info.get(info, defaults.view()), info.default_value) << info.name;
    EXPECT_NE(std::string(info.meaning), "") << info.name;
    EXPECT_NE(std::string(info.section), "") << info.name;
    EXPECT_TRUE(info.values.empty() != (info.number_range == nullptr)) << info.name;
  }
  // The readings issue 21 asks for, beside the six that existed before.
  for (const char* name : {"crc_coverage",
                           "ack_byte_order",
                           "laser_status_byte_order",
                           "angle_command_scale",
                           "gimbal_system_id",
                           "camera_system_id",
                           "yaw_sign",
                           "pitch_sign",
                           "roll_sign",
                           "attitude_order",
                           "yaw_range",
                           "sd_capacity_unit",
                           "shutter_field",
                           "enhancement_switch",
                           "thermal_zoom_code",
                           "calibration_end",
                           "photo_mode_2",
                           "gps_request_time",
                           "gps_answer_byte_order",
                           "laser_target_zeros",
                           "focus_plus"})
    EXPECT_NE(find_convention(name), nullptr) << name;
}

TEST(ConventionsTable, EveryValueSetsAndReadsBack) {
  for (const ConventionInfo& info : convention_table()) {
    for (const char* value : info.values) {
      AllReadings r;
      ASSERT_TRUE(set_convention(r.refs(), info.name, value).is_ok()) << info.name << "=" << value;
      EXPECT_EQ(info.get(info, r.view()), value) << info.name;
    }
  }
  AllReadings r;
  ASSERT_TRUE(set_convention_assignment(r.refs(), "yaw_sign=left").is_ok());
  EXPECT_EQ(r.codec.conventions.yaw_sign, YawSign::kLeft);
  ASSERT_TRUE(set_convention_assignment(r.refs(), "sd_capacity_unit=0.1mb").is_ok());
  EXPECT_EQ(r.codec.conventions.sd_capacity_unit, SdCapacityUnit::kTenthMb);
  ASSERT_TRUE(set_convention_assignment(r.refs(), "ack_byte_order=little").is_ok());
  EXPECT_EQ(r.codec.ack_byte_order, ByteOrder::kLittle);
  ASSERT_TRUE(set_convention_assignment(r.refs(), "crc_coverage=whole_frame").is_ok());
  EXPECT_EQ(r.crc_coverage, CrcCoverage::kWholeFrame);
  ASSERT_TRUE(set_convention_assignment(r.refs(), "gimbal_system_id=4").is_ok());
  EXPECT_EQ(r.codec.gimbal_address.system, 4);
  ASSERT_TRUE(set_convention_assignment(r.refs(), "angle_command_scale=10").is_ok());
  EXPECT_EQ(r.codec.angle_command_scale, 10);
}

TEST(ConventionsTable, BadTextIsRefusedWithTheNameAndTheValuesAndChangesNothing) {
  AllReadings r;
  Status s = set_convention_assignment(r.refs(), "yaw_sign=up");
  ASSERT_FALSE(s.is_ok());
  EXPECT_EQ(s.message(), "yaw_sign must be right or left, got 'up'");
  EXPECT_EQ(r.codec.conventions.yaw_sign, YawSign::kRight);

  s = set_convention_assignment(r.refs(), "shutter_field=ms");
  EXPECT_EQ(s.message(), "shutter_field must be us, us_wrapped or 100us, got 'ms'");

  s = set_convention_assignment(r.refs(), "yaw_sing=left");
  ASSERT_FALSE(s.is_ok());
  EXPECT_NE(s.message().find("no convention named 'yaw_sing'"), std::string::npos);
  EXPECT_NE(s.message().find("yaw_sign"), std::string::npos);

  EXPECT_FALSE(set_convention_assignment(r.refs(), "yaw_sign").is_ok());
  s = set_convention_assignment(r.refs(), "gimbal_system_id=256");
  EXPECT_EQ(s.message(), "gimbal_system_id must be a whole number 0..255, got '256'");
  EXPECT_FALSE(set_convention_assignment(r.refs(), "angle_command_scale=10x").is_ok());
  EXPECT_FALSE(set_convention_assignment(r.refs(), "angle_command_scale=").is_ok());
  EXPECT_EQ(r.codec.gimbal_address.system, 3);
  EXPECT_EQ(r.codec.angle_command_scale, 100);
}

}  // namespace
}  // namespace k40t::protocol
