// Validation of the thermal camera's messages (document section 3.2.2) beyond the golden frames of
// test_thermal_messages.cpp: the measured area stays inside the sensor, and the enums hold exactly
// the document's codes.
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "golden_checks.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "message_checks.h"

namespace k40t::protocol {
namespace {

using testing::defined_codes;
using testing::expect_range_error;

ThermalAreaRequest area(uint16_t w, uint16_t h, uint16_t cx, uint16_t cy) {
  return {w, h, cx, cy};  // width_px, height_px, center_x_px, center_y_px
}

TEST(ThermalAreaRequest, RectangleMustStayInsideTheMeasurableArea) {  // note of 3.2.2.11
  EXPECT_TRUE(area(959, 991, 799, 527).validate()) << "x 320..1278, y 32..1022, the largest";
  EXPECT_TRUE(area(1, 1, 320, 32).validate()) << "one pixel in the corner";
  EXPECT_TRUE(area(2, 2, 1278, 1022).validate()) << "x 1277..1279, y 1021..1023";
  EXPECT_FALSE(area(2, 2, 1279, 1022).validate()) << "x 1278..1280";
  const ThermalAreaRequest valid = area(200, 100, 800, 500);
  expect_range_error(valid, "width_px", [](auto& m) { m.width_px = 0; });
  expect_range_error(valid, "height_px", [](auto& m) { m.height_px = 0; });
  expect_range_error(valid, "center_x_px", [](auto& m) { m.center_x_px = 319; });
  expect_range_error(valid, "center_y_px", [](auto& m) { m.center_y_px = 1024; });
  // centre inside, but the rectangle pokes out on the left: x 250..450
  expect_range_error(valid, "center_x_px", [](auto& m) { m.center_x_px = 350; });
  expect_range_error(valid, "width_px", [](auto& m) { m.center_x_px = 350; });
  // and at the bottom: y 1000..1020 is fine, 1004..1024 is not
  expect_range_error(area(20, 20, 600, 1010), "height_px", [](auto& m) { m.center_y_px = 1014; });
  const auto refused = encode_payload(area(200, 100, 350, 500));
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("x 250..450"), std::string::npos) << refused.error();
  EXPECT_NE(refused.error().find("320..1279"), std::string::npos) << refused.error();
}

// ---- enums ----------------------------------------------------------------------------------

TEST(ThermalEnums, AllTwentyPalettesHaveTheDocumentsNames) {  // 3.2.2.3
  const char* names[] = {
      "white_hot",      "black_hot",       "rainbow",       "high_contrast_rainbow",
      "iron_red",       "magma",           "sky",           "medium_grey",
      "grey_red",       "purple_orange",   "special_1",     "warning_red",
      "ice_fire",       "cyan_red",        "special_2",     "gradient_red",
      "gradient_green", "gradient_yellow", "warning_green", "warning_blue"};
  for (int code = 1; code <= 20; ++code) {
    const char* name = to_string(static_cast<Palette>(code));
    ASSERT_NE(name, nullptr) << code;
    EXPECT_STREQ(name, names[code - 1]) << code;
  }
  EXPECT_EQ(to_string(static_cast<Palette>(0)), nullptr);
  EXPECT_EQ(to_string(static_cast<Palette>(21)), nullptr);
  EXPECT_EQ(to_string(static_cast<Palette>(255)), nullptr);
}

TEST(ThermalEnums, OtherEnumsDefineExactlyTheDocumentsCodes) {
  EXPECT_EQ(defined_codes<ThermalGainMode>(), (std::set<int>{0, 1, 2}));
  EXPECT_STREQ(to_string(ThermalGainMode::kAuto), "auto");
  EXPECT_EQ(defined_codes<ThermalMeasurementType>(), (std::set<int>{0, 1}));
  EXPECT_STREQ(to_string(ThermalMeasurementType::kArea), "area");
  EXPECT_EQ(defined_codes<ThermalCoreType>(), (std::set<int>{0, 1}));
  EXPECT_STREQ(to_string(ThermalCoreType::kRadiometric), "radiometric");
}

TEST(ThermalEnums, EnumErrorListsTheAllowedCodes) {
  ThermalGainModeRequest gain;
  gain.gain_mode = static_cast<ThermalGainMode>(7);
  const Status status = gain.validate();
  ASSERT_FALSE(status);
  EXPECT_NE(status.message().find("0 (high), 1 (low), 2 (auto)"), std::string::npos)
      << status.message();
}

}  // namespace
}  // namespace k40t::protocol
