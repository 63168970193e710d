// The document's open readings end to end (docs/protocol/decisions.md#conventions): the simulator
// plays a reading, and (b) the driver core loaded with the same reading gives the simulator's
// truth, (c) a driver with another reading says so in the `conventions` diagnostic.
#include <gtest/gtest.h>

#include <cmath>

#include "conventions_rig.h"
#include "k40t_driver/protocol/messages/gimbal.h"
#include "k40t_driver/protocol/messages/thermal.h"
#include "k40t_driver/protocol/messages/visible.h"

namespace k40t::driver::testing {
namespace {

namespace p = protocol;
using test::eventually;

// Right 30 deg, down 20 deg (0x000012's direction bytes: unambiguous).
p::GimbalAngleRequest right30_down20() {
  p::GimbalAngleRequest move;
  move.yaw_deg = 30;
  move.pitch_deg = -20;
  return move;
}

bool near(double a, double b, double tolerance = 0.2) {
  return std::abs(a - b) < tolerance;
}

TEST(ConventionsEndToEnd, MirroredSignsWithTheRightReadingGiveTheTruth) {
  ConventionsRig rig({"yaw_sign=left", "pitch_sign=down"}, {"yaw_sign=left", "pitch_sign=down"});
  ASSERT_TRUE(rig.driver().request(right30_down20()).ok());
  ASSERT_TRUE(eventually([&] {
    const auto a = rig.attitude();
    return a && near(a->joint_yaw_deg, 30, 0.02) && near(a->joint_pitch_deg, -20, 0.02);
  })) << "the driver's joints never reached right 30, down 20";
  const sim::YawPitchRoll truth = rig.true_joints();  // the gimbal has stopped there
  EXPECT_NEAR(truth.yaw, 30, 0.02);
  EXPECT_NEAR(truth.pitch, -20, 0.02);
  EXPECT_EQ(rig.reading("yaw_sign").contradiction, "");
  EXPECT_EQ(rig.reading("yaw_sign").source, "parameter");
}

TEST(ConventionsEndToEnd, MirroredSignsWithTheDefaultsAreNamed) {
  ConventionsRig rig({"yaw_sign=left", "pitch_sign=down"}, {});
  ASSERT_TRUE(rig.driver().request(right30_down20()).ok());
  ASSERT_TRUE(rig.contradicts("yaw_sign"));
  ASSERT_TRUE(rig.contradicts("pitch_sign"));
  const std::string why = rig.reading("yaw_sign").contradiction;
  EXPECT_NE(why.find("0x000012 yaw 30.00 deg right"), std::string::npos) << why;
  EXPECT_NE(why.find("yaw_sign: left"), std::string::npos) << why;
}

TEST(ConventionsEndToEnd, ADirectionCommandCountedTheOtherWayIsNamed) {
  ConventionsRig rig({"yaw_sign=left"}, {});
  p::GimbalControlRequest left;
  left.yaw = p::GimbalYawDirection::kLeft;
  ASSERT_TRUE(rig.driver().request(left).ok());
  ASSERT_TRUE(rig.contradicts("yaw_sign"));
  EXPECT_NE(rig.reading("yaw_sign").contradiction.find("0x000010 yaw left"), std::string::npos);
  EXPECT_TRUE(rig.driver().request(p::GimbalControlRequest{}).ok());  // stop
  EXPECT_EQ(rig.reading("pitch_sign").contradiction, "");
}

p::GimbalAngleRequest left30() {
  p::GimbalAngleRequest move;
  move.yaw_deg = -30;
  move.pitch_move = false;
  return move;
}

TEST(ConventionsEndToEnd, AHeadingYawLocksAutoAndReadsSigned) {
  ConventionsRig rig({"yaw_range=heading"}, {});
  ASSERT_TRUE(rig.driver().request(left30()).ok());
  // 330 deg as a heading: the driver publishes -30 (left 30), as the truth.
  ASSERT_TRUE(eventually([&] {
    const auto a = rig.attitude();
    return a && near(a->joint_yaw_deg, -30, 0.02);
  }));
  EXPECT_NEAR(rig.true_joints().yaw, -30, 0.02);
  EXPECT_EQ(rig.reading("yaw_range").value, "heading");
  EXPECT_NE(rig.reading("yaw_range").source.find("detected from 0x000002"), std::string::npos);
}

TEST(ConventionsEndToEnd, AWrongYawRangeIsNamed) {
  ConventionsRig heading_pod({"yaw_range=heading"}, {"yaw_range=signed"});
  ASSERT_TRUE(heading_pod.driver().request(left30()).ok());
  EXPECT_TRUE(heading_pod.contradicts("yaw_range"));
  ConventionsRig signed_pod({}, {"yaw_range=heading"});
  ASSERT_TRUE(signed_pod.driver().request(left30()).ok());
  EXPECT_TRUE(signed_pod.contradicts("yaw_range"));
}

TEST(ConventionsEndToEnd, SdCapacitiesInTenthsOfAMegabyte) {
  auto small_card = [](sim::SimOptions& o) { o.pod.camera.sd.capacity_mb = 4000; };
  ConventionsRig right({"sd_capacity_unit=0.1mb"}, {"sd_capacity_unit=0.1mb"}, small_card);
  ASSERT_TRUE(eventually([&] { return right.camera().has_value(); }));
  EXPECT_NEAR(right.camera()->sd_total_mb, 4000, 0.1);
  ConventionsRig tens({}, {}, small_card);
  ASSERT_TRUE(eventually([&] { return tens.camera().has_value(); }));
  EXPECT_NEAR(tens.camera()->sd_total_mb, 4000, 10);
}

// 1/4 s under every shutter reading: what the driver makes of the pod's 16 bits.
TEST(ConventionsEndToEnd, AQuarterSecondShutterUnderEveryReading) {
  for (const char* field : {"us", "us_wrapped", "100us"}) {
    const std::string c = std::string("shutter_field=") + field;
    ConventionsRig rig({c}, {c});
    p::VisibleShutterRequest quarter;
    quarter.shutter = p::Shutter::k1_4;
    ASSERT_TRUE(rig.driver().request(quarter).ok()) << field;
    const p::ShutterField reading = rig.driver().codec().conventions.shutter_field;
    double us = 0;
    const double expected = reading == p::ShutterField::kMicroseconds ? 65535 : 250000;
    EXPECT_TRUE(eventually([&] {
      const auto v = rig.visible();
      us = v ? p::shutter_us_from_wire(v->shutter_us, reading) : 0;
      return us == expected;
    })) << field
        << ": got " << us << " us";
  }
}

p::ThermalSettingsAck enhancement_read_back(ConventionsRig& rig, uint8_t level) {
  p::ThermalEnhancementRequest set;
  set.enhancement_level = level;
  EXPECT_TRUE(rig.driver().request(set).ok());
  Result<p::ThermalSettingsAck> ack = rig.driver().request_typed(p::ThermalReadSettingsRequest{});
  EXPECT_TRUE(ack) << ack.error();
  return ack ? *ack : p::ThermalSettingsAck{};
}

TEST(ConventionsEndToEnd, EnhancementLevelUnderEveryReading) {
  for (const char* reading : {"bit7", "bit0", "level"}) {
    const std::string c = std::string("enhancement_switch=") + reading;
    ConventionsRig rig({c}, {c});
    const p::ThermalSettingsAck on = enhancement_read_back(rig, 5);
    EXPECT_TRUE(on.enhancement_on) << reading;
    EXPECT_EQ(on.enhancement_level, 5) << reading;
    const p::ThermalSettingsAck off = enhancement_read_back(rig, 0);
    EXPECT_FALSE(off.enhancement_on) << reading;
    EXPECT_EQ(rig.reading("enhancement_switch").contradiction, "") << reading;
  }
}

TEST(ConventionsEndToEnd, AWrongEnhancementSwitchIsNamed) {
  ConventionsRig rig({"enhancement_switch=bit0"}, {});
  enhancement_read_back(rig, 5);  // 0x0B: level 11 under bit7
  const std::string why = rig.reading("enhancement_switch").contradiction;
  EXPECT_NE(why.find("0x0B"), std::string::npos) << why;
  EXPECT_NE(why.find("fits bit0"), std::string::npos) << why;
}

TEST(ConventionsEndToEnd, ZeroBasedThermalZoom) {
  ConventionsRig right({"thermal_zoom_code=zero_based"}, {"thermal_zoom_code=zero_based"});
  p::ThermalZoomRequest zoom;
  zoom.zoom_x = 2;
  ASSERT_TRUE(right.driver().request(zoom).ok());
  Result<p::ThermalSettingsAck> ack = right.driver().request_typed(p::ThermalReadSettingsRequest{});
  ASSERT_TRUE(ack) << ack.error();
  EXPECT_EQ(ack->zoom_x, 2);
  ConventionsRig wrong({"thermal_zoom_code=zero_based"}, {});
  ASSERT_TRUE(wrong.driver().request_typed(p::ThermalReadSettingsRequest{}));  // zoom 1: code 0
  EXPECT_NE(wrong.reading("thermal_zoom_code").contradiction.find("fits zero_based"),
            std::string::npos);
}

}  // namespace
}  // namespace k40t::driver::testing
