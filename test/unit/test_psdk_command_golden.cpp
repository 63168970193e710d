// PSDK command DATA written by hand, byte by byte, from the protocol document (section cited per
// test; all fields little-endian, 2.1 and 3.3.9): each struct must encode to exactly these bytes
// and decode them back to the same physical values.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "k40t_driver/psdk/commands/all.h"
#include "message_text.h"
#include "psdk_data_codec.h"

namespace k40t::psdk {
namespace {

using test::Bytes;
using test::decoded;
using test::encoded;
using testing::fields_are;
using testing::message_from_text;

// 3.3.4: double longitude 2.0 rad, double latitude -0.5 rad, int16 12.3 m as 123 (0.1 m),
// 14 satellites, signal 3 (very strong).
const Bytes kGps = {0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x40, 0x00, 0x00,
                    0x00, 0x00, 0x00, 0x00, 0xe0, 0xbf, 0x7b, 0x00, 0x0e, 0x03};

TEST(PsdkGolden, GpsPush) {
  const char fields[] =
      "longitude_rad=2.0 latitude_rad=-0.5 relative_height_m=12.3 satellites=14 signal=very_strong";
  EXPECT_EQ(encoded(message_from_text<GpsPush>(fields)), kGps);
  EXPECT_TRUE(fields_are(decoded<GpsPush>(kGps), fields));
}

// 3.3.5: byte 1 = bit 1 motors rotating + bits 2-3 = 2 (in the sky) = 0x0A; uint16 123.4 s as
// 1234 (0.1 s) = 0x04D2; drone type 8 (M210 RTK V2).
const Bytes kUavState = {0x0a, 0xd2, 0x04, 0x08};

TEST(PsdkGolden, UavStatePush) {
  const std::string fields =
      "motors_rotating=true landing=in_the_sky flight_time_s=123.4 drone_type=M210_RTK_V2";
  EXPECT_EQ(encoded(message_from_text<UavStatePush>(fields)), kUavState);
  EXPECT_TRUE(fields_are(decoded<UavStatePush>(kUavState), fields + " compass_abnormal=false"));
}

// 3.3.1: 42 bytes. baseband 1, max bandwidth 20, reserved 0, connection bits 0 (RC) + 3 (app)
// = 0x09, MSDK up max 1000, down max 2000, network max 8000, flags bits 0 + 2 = 0x05, MSDK up
// 100, down 200, video 4000, data 16, OSDK up max 65536, flag 0x01, OSDK up 256.
const Bytes kBandwidth = {0x01, 0x14, 0x00, 0x09, 0xe8, 0x03, 0x00, 0x00, 0xd0, 0x07, 0x00,
                          0x00, 0x40, 0x1f, 0x00, 0x00, 0x05, 0x64, 0x00, 0x00, 0x00, 0xc8,
                          0x00, 0x00, 0x00, 0xa0, 0x0f, 0x00, 0x00, 0x10, 0x00, 0x00, 0x00,
                          0x00, 0x00, 0x01, 0x00, 0x01, 0x00, 0x01, 0x00, 0x00};

TEST(PsdkGolden, LinkBandwidthPush) {
  const auto m = message_from_text<LinkBandwidthPush>(
      "image_link_normal=true max_image_link_bandwidth=20 remote_controller_connected=true "
      "app_connected=true msdk_uplink_max_bytes_s=1000 msdk_downlink_max_bytes_s=2000 "
      "network_max_kbit_s=8000 msdk_uplink_within_limit=true network_within_limit=true "
      "msdk_uplink_bytes_s=100 msdk_downlink_bytes_s=200 network_video_kbit_s=4000 "
      "network_data_kbit_s=16 osdk_uplink_max_bytes_s=65536 osdk_uplink_within_limit=true "
      "osdk_uplink_bytes_s=256");
  ASSERT_EQ(kBandwidth.size(), 42u);
  EXPECT_EQ(encoded(m), kBandwidth);
  EXPECT_TRUE(fields_are(decoded<LinkBandwidthPush>(kBandwidth),
                         "app_connected=true image_downlink_connected=false "
                         "msdk_downlink_within_limit=false osdk_uplink_max_bytes_s=65536 "
                         "osdk_uplink_bytes_s=256"));
}

// 3.3.2: floats 1.0, -0.5, 0.0, 0.25.
const Bytes kAttitude = {0x00, 0x00, 0x80, 0x3f, 0x00, 0x00, 0x00, 0xbf,
                         0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x80, 0x3e};

TEST(PsdkGolden, AttitudePush) {
  const AttitudePush m{{}, 1.0f, -0.5f, 0.0f, 0.25f};  // q0, q1, q2, q3
  EXPECT_EQ(encoded(m), kAttitude);
  const AttitudePush d = decoded<AttitudePush>(kAttitude);
  EXPECT_EQ(d.q1, -0.5f);
  EXPECT_EQ(d.q3, 0.25f);
}

// 3.3.3: 15 %, power off soon; its ACK: OK, preparation complete.
TEST(PsdkGolden, BatteryPushAndAck) {
  BatteryInfoPush m;
  m.percentage = 15;
  m.power_off_soon = true;
  EXPECT_EQ(encoded(m), (Bytes{0x0f, 0x01}));
  BatteryInfoAck ack;
  ack.power_off_ready = true;
  EXPECT_EQ(encoded(ack), (Bytes{0x00, 0x01}));
  EXPECT_TRUE(decoded<BatteryInfoAck>({0x00, 0x01}).power_off_ready);
}

// 3.3.10: 2024-02-29 23:59:60 (a leap second) + 999999 us = 0x000F423F.
const Bytes kUtc = {0xe8, 0x07, 0x02, 0x1d, 0x17, 0x3b, 0x3c, 0x3f, 0x42, 0x0f, 0x00};

TEST(PsdkGolden, UtcTimePush) {
  UtcTimePush m;
  m.time = {2024, 2, 29, 23, 59, 60};
  m.microsecond = 999999;
  EXPECT_EQ(encoded(m), kUtc);
  const UtcTimePush d = decoded<UtcTimePush>(kUtc);
  EXPECT_EQ(d.time.year, 2024);
  EXPECT_EQ(d.time.second, 60);
  EXPECT_EQ(d.microsecond, 999999u);
}

// docs/psdk.md#frames' ACK vector DATA: code 0, then {debug 0, modify 0, minor 3, major 1}.
TEST(PsdkGolden, PsdkVersionAck) {
  PsdkVersionAck m;
  m.version = {1, 3, 0, 0};
  EXPECT_EQ(encoded(m), (Bytes{0x00, 0x00, 0x00, 0x03, 0x01}));
  const PsdkVersionAck d = decoded<PsdkVersionAck>({0x00, 0x04, 0x03, 0x02, 0x01});
  EXPECT_EQ(d.version.major, 1);
  EXPECT_EQ(d.version.minor, 2);
  EXPECT_EQ(d.version.modify, 3);
  EXPECT_EQ(d.version.debug, 4);
}

// 3.4.9: code 0; state bits 0 (inserted) + 3 (formatted) + 8 (error) = 0x0109; capacity 30528
// MB, remaining 1024 MB, 500 shots, 3600 s.
const Bytes kSdCard = {0x00, 0x09, 0x01, 0x40, 0x77, 0x00, 0x00, 0x00, 0x04, 0x00,
                       0x00, 0xf4, 0x01, 0x00, 0x00, 0x10, 0x0e, 0x00, 0x00};

TEST(PsdkGolden, SdCardInfoAck) {
  EXPECT_EQ(encoded(message_from_text<SdCardInfoAck>(
                "inserted=true formatted=true has_error=true capacity_mb=30528 remaining_mb=1024 "
                "remaining_shots=500 remaining_record_time_s=3600")),
            kSdCard);
  EXPECT_TRUE(
      fields_are(decoded<SdCardInfoAck>(kSdCard), "has_error=true full=false capacity_mb=30528"));
}

// 3.4.13: column 11 in bits 0-3, row 7 in bits 4-7.
TEST(PsdkGolden, SpotMeteringZone) {
  SetSpotMeteringZone m;
  m.zone = {11, 7};
  EXPECT_EQ(encoded(m), (Bytes{0x7b}));
  const SetSpotMeteringZone d = decoded<SetSpotMeteringZone>({0x52});
  EXPECT_EQ(d.zone.column, 2);
  EXPECT_EQ(d.zone.row, 5);
}

// 3.4.22 (read as uint16 0.1 mm, docs/psdk.md): 317.0 mm = 3170 = 0x0C62.
TEST(PsdkGolden, OpticalZoomFocalLength) {
  SetOpticalZoomFocalLength m;
  m.focal_length_mm = 317.0;
  EXPECT_EQ(encoded(m), (Bytes{0x62, 0x0c}));
  EXPECT_DOUBLE_EQ(decoded<OpticalZoomFocalLengthAck>({0x00, 0x41, 0x00}).focal_length_mm, 6.5);
}

// 3.4.25: speed 78 (fastest), direction 0 (zoom out).
TEST(PsdkGolden, StartContinuousZoom) {
  StartContinuousZoom m;
  m.speed = ZoomSpeed::kFastest;
  m.direction = ZoomDirection::kOut;
  EXPECT_EQ(encoded(m), (Bytes{0x4e, 0x00}));
}

// 3.5.1: code 0, mode 2 (FPV in 3.5.1's numbering), bits 0 (upward) + 3 (pitch limit) = 0x09,
// int16 pitch -90.0 deg = -900 = 0xFC7C, roll 0.5 deg = 5, yaw 179.9 deg = 1799 = 0x0707.
const Bytes kGimbalState = {0x00, 0x02, 0x09, 0x7c, 0xfc, 0x05, 0x00, 0x07, 0x07};

TEST(PsdkGolden, GimbalStateAck) {
  GimbalStateAck m;
  m.mode = GimbalStateMode::kFpv;
  m.flags.upward_mounted = true;
  m.flags.pitch_at_limit = true;
  m.angles = {-90.0, 0.5, 179.9};
  EXPECT_EQ(encoded(m), kGimbalState);
  const GimbalStateAck d = decoded<GimbalStateAck>(kGimbalState);
  EXPECT_EQ(d.mode, GimbalStateMode::kFpv);
  EXPECT_TRUE(d.flags.upward_mounted);
  EXPECT_FALSE(d.flags.yaw_at_limit);
  EXPECT_DOUBLE_EQ(d.angles.pitch_deg, -90.0);
  EXPECT_DOUBLE_EQ(d.angles.yaw_deg, 179.9);
}

// 3.5.2: FPV is 1 in 3.5.2's numbering.
TEST(PsdkGolden, SetGimbalModeUsesItsOwnNumbering) {
  SetGimbalMode m;
  m.mode = GimbalMode::kFpv;
  EXPECT_EQ(encoded(m), (Bytes{0x01}));
  EXPECT_EQ(to_state_mode(GimbalMode::kFpv), GimbalStateMode::kFpv);
  EXPECT_EQ(to_state_mode(GimbalMode::kFollowing), GimbalStateMode::kFollowing);
}

// 3.5.4: pitch -180 deg/s = -1800 = 0xF8F8, roll 0, yaw 45.5 deg/s = 455 = 0x01C7, action 1.
TEST(PsdkGolden, ControlGimbalSpeed) {
  ControlGimbalSpeed m;
  m.pitch_rate_deg_s = -180.0;
  m.roll_rate_deg_s = 0.0;
  m.yaw_rate_deg_s = 45.5;
  m.action = GimbalControlAction::kControl;
  EXPECT_EQ(encoded(m), (Bytes{0xf8, 0xf8, 0x00, 0x00, 0xc7, 0x01, 0x01}));
}

// 3.2.7: code 0, 2 widgets: {type 2 switch, index 0, value 1}, {type 3 range bar, index 4,
// value -2}.
const Bytes kWidgetGroup = {0x00, 0x02, 0x02, 0x00, 0x01, 0x00, 0x00,
                            0x00, 0x03, 0x04, 0xfe, 0xff, 0xff, 0xff};

TEST(PsdkGolden, WidgetGroupDataAck) {
  WidgetGroupDataAck m;
  m.count = 2;
  m.widgets[0] = {WidgetType::kSwitch, 0, 1};
  m.widgets[1] = {WidgetType::kRangeBar, 4, -2};
  EXPECT_EQ(encoded(m), kWidgetGroup);
  const WidgetGroupDataAck d = decoded<WidgetGroupDataAck>(kWidgetGroup);
  ASSERT_EQ(d.count, 2);
  EXPECT_EQ(d.widgets[1].type, WidgetType::kRangeBar);
  EXPECT_EQ(d.widgets[1].value, -2);
}

// 3.2.5: code 0, type 5 (integer input box), index 1, name "Zoom" in 32 bytes, then the 32-byte
// text shown after the number, "x".
TEST(PsdkGolden, WidgetListDataAckInputBox) {
  Bytes expected = {0x00, 0x05, 0x01, 'Z', 'o', 'o', 'm'};
  expected.resize(3 + 32, 0x00);
  expected.push_back('x');
  expected.resize(3 + 32 + 32, 0x00);
  WidgetListDataAck m;
  m.type = WidgetType::kIntegerInputBox;
  m.index = 1;
  m.name = "Zoom";
  m.input_box_suffix = "x";
  EXPECT_EQ(encoded(m), expected);
  const WidgetListDataAck d = decoded<WidgetListDataAck>(expected);
  EXPECT_EQ(d.name, "Zoom");
  EXPECT_EQ(d.input_box_suffix, "x");
}

// 3.2.5: a button ends after its name: 35 bytes with the code.
TEST(PsdkGolden, WidgetListDataAckButtonEndsAfterTheName) {
  WidgetListDataAck m;
  m.type = WidgetType::kButton;
  m.name = "Photo";
  EXPECT_EQ(encoded(m).size(), 35u);
}

// 3.2.3: the text and its terminating NUL.
TEST(PsdkGolden, FloatingWindowMessage) {
  FloatingWindowMessage m;
  m.text = "hi";
  EXPECT_EQ(encoded(m), (Bytes{'h', 'i', 0x00}));
  EXPECT_EQ(decoded<FloatingWindowMessage>({'o', 'k', 0x00}).text, "ok");
}

// 3.7.1: 1 point, task 2, 2024-06-30 12:34:56, event 5 | target point 3 << 13 = 0x6005,
// offset 1500000 us = 0x0016E360.
const Bytes kGetPosition = {0x01, 0x02, 0xe8, 0x07, 0x06, 0x1e, 0x0c, 0x22,
                            0x38, 0x05, 0x60, 0x60, 0xe3, 0x16, 0x00};

TEST(PsdkGolden, GetPosition) {
  GetPosition m;
  m.count = 1;
  m.task_index = 2;
  m.base_time = {2024, 6, 30, 12, 34, 56};
  m.points[0].event = {5, 3};
  m.points[0].time_offset_us = 1500000;
  EXPECT_EQ(encoded(m), kGetPosition);
  const GetPosition d = decoded<GetPosition>(kGetPosition);
  EXPECT_EQ(d.points[0].event.event_index, 5);
  EXPECT_EQ(d.points[0].event.target_point_index, 3);
  EXPECT_EQ(d.points[0].time_offset_us, 1500000u);
}

// 3.7.1 ACK: one target point is 56 bytes after the 10-byte head (code included).
TEST(PsdkGolden, GetPositionAckSize) {
  GetPositionAck m;
  m.count = 1;
  m.points[0].solution = PositionSolution::kFixed;
  const Bytes b = encoded(m);
  ASSERT_EQ(b.size(), 10u + 56u);
  EXPECT_EQ(b[16], 50);  // byte 17: solution property
}

}  // namespace
}  // namespace k40t::psdk
