// DATA of commands and pushes the SKYPORT bridge handles, written by hand, byte by byte, from the
// PSDK protocol document (section cited per test; little-endian, 2.1), and the layouts where DJI's
// published PSDK 1.x headers disagree with it (docs/psdk.md P28..P31), written from the headers.
// Each struct must decode these bytes to the values stated, and encode the values to these bytes.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "k40t_driver/psdk/commands/all.h"
#include "psdk_data_codec.h"
#include "k40t_driver/psdk/commands/header_variants.h"

namespace k40t::psdk {
namespace {

using test::Bytes;
using test::decoded;
using test::encoded;

// 3.4.8 ACK: code 0, recording 1, uint16 duration 75 s = 0x004B.
TEST(PsdkBridgeGolden, RecordStateAck) {
  const Bytes bytes = {0x00, 0x01, 0x4B, 0x00};
  RecordStateAck m;
  m.recording = true;
  m.duration_s = 75;
  EXPECT_EQ(encoded(m), bytes);
  const RecordStateAck d = decoded<RecordStateAck>(bytes);
  EXPECT_TRUE(d.recording);
  EXPECT_EQ(d.duration_s, 75);
}

// 3.4.17: float x 0.5 = 0x3F000000, float y 0.25 = 0x3E800000.
TEST(PsdkBridgeGolden, SetFocusZone) {
  const Bytes bytes = {0x00, 0x00, 0x00, 0x3F, 0x00, 0x00, 0x80, 0x3E};
  const SetFocusZone d = decoded<SetFocusZone>(bytes);
  EXPECT_EQ(d.x, 0.5f);
  EXPECT_EQ(d.y, 0.25f);
  EXPECT_EQ(encoded(d), bytes);
}

// 3.4.19: float factor 2.0 = 0x40000000.
TEST(PsdkBridgeGolden, SetDigitalZoomFactor) {
  const Bytes bytes = {0x00, 0x00, 0x00, 0x40};
  EXPECT_EQ(decoded<SetDigitalZoomFactor>(bytes).factor_x, 2.0f);
}

// 3.4.21 ACK: code 0, uint16 max 51.7 mm = 517 = 0x0205, min 4.7 mm = 47 = 0x002F, step 0.1 mm =
// 1, each in 0.1 mm.
TEST(PsdkBridgeGolden, OpticalZoomSpecAck) {
  const Bytes bytes = {0x00, 0x05, 0x02, 0x2F, 0x00, 0x01, 0x00};
  OpticalZoomSpecAck m;
  m.max_focal_length_mm = 51.7;
  m.min_focal_length_mm = 4.7;
  m.focal_length_step_mm = 0.1;
  EXPECT_EQ(encoded(m), bytes);
}

// 3.5.6: int16 pitch -30.0 deg = -300 = 0xFED4, roll 0, yaw 20.0 deg = 200 = 0x00C8 (0.1 deg;
// signed although the document says Uint16, P16).
TEST(PsdkBridgeGolden, ControlGimbalJointAngle) {
  const Bytes bytes = {0xD4, 0xFE, 0x00, 0x00, 0xC8, 0x00};
  const ControlGimbalJointAngle d = decoded<ControlGimbalJointAngle>(bytes);
  EXPECT_DOUBLE_EQ(d.angles.pitch_deg, -30.0);
  EXPECT_DOUBLE_EQ(d.angles.roll_deg, 0.0);
  EXPECT_DOUBLE_EQ(d.angles.yaw_deg, 20.0);
}

// 3.5.8 ACK: code 0, progress 40 % = 0x28, status 1 (processing).
TEST(PsdkBridgeGolden, CalibrationProgressAck) {
  const Bytes bytes = {0x00, 0x28, 0x01};
  CalibrationProgressAck m;
  m.progress_percent = 40;
  m.status = CalibrationStatus::kInProgress;
  EXPECT_EQ(encoded(m), bytes);
}

// 3.5.9 ACK: code 0, floats in 0.1 deg/s: pitch 5 deg/s = 50.0 = 0x42480000, roll 0, yaw -10 deg/s
// = -100.0 = 0xC2C80000.
TEST(PsdkBridgeGolden, GimbalAdditionalStatusAck) {
  const Bytes bytes = {0x00, 0x00, 0x00, 0x48, 0x42, 0x00, 0x00,
                       0x00, 0x00, 0x00, 0x00, 0xC8, 0xC2};
  GimbalAdditionalStatusAck m;
  m.pitch_rate_deg_s = 5;
  m.roll_rate_deg_s = 0;
  m.yaw_rate_deg_s = -10;
  EXPECT_EQ(encoded(m), bytes);
}

// 3.2.8: widget type 1 (button), index 2, int32 value 1 (pressed).
TEST(PsdkBridgeGolden, SetWidgetValue) {
  const Bytes bytes = {0x01, 0x02, 0x01, 0x00, 0x00, 0x00};
  const SetWidgetValue d = decoded<SetWidgetValue>(bytes);
  EXPECT_EQ(d.widget.type, WidgetType::kButton);
  EXPECT_EQ(d.widget.index, 2);
  EXPECT_EQ(d.widget.value, 1);
}

// 3.1.4 ACK: code 0, product name in bytes 2:33, product id in 34:49, developer account in
// 50:113, each NUL-padded.
TEST(PsdkBridgeGolden, ProductInfoAck) {
  Bytes bytes(113, 0x00);
  const std::string name = "k40t_test", id = "123456", account = "dev@example.com";
  std::copy(name.begin(), name.end(), bytes.begin() + 1);
  std::copy(id.begin(), id.end(), bytes.begin() + 33);
  std::copy(account.begin(), account.end(), bytes.begin() + 49);
  ProductInfoAck m;
  m.product_name = name;
  m.product_id = id;
  m.developer_account = account;
  EXPECT_EQ(encoded(m), bytes);
}

// 3.3.10: uint16 year 2024 = 0x07E8, month 7, day 1, hour 12, minute 30, second 15, uint32
// microsecond 250000 = 0x0003D090. A microsecond of 1000000 = 0x000F4240 is out of range: it
// decodes (the codec reports what was sent) but does not validate, so the bridge drops it.
TEST(PsdkBridgeGolden, UtcTimePushAndItsRange) {
  const Bytes bytes = {0xE8, 0x07, 0x07, 0x01, 0x0C, 0x1E, 0x0F, 0x90, 0xD0, 0x03, 0x00};
  const UtcTimePush d = decoded<UtcTimePush>(bytes);
  EXPECT_EQ(d.time.year, 2024);
  EXPECT_EQ(d.time.second, 15);
  EXPECT_EQ(d.microsecond, 250000u);
  EXPECT_TRUE(validate(d));
  const Bytes too_many_us = {0xE8, 0x07, 0x07, 0x01, 0x0C, 0x1E, 0x0F, 0x40, 0x42, 0x0F, 0x00};
  EXPECT_FALSE(validate(decoded<UtcTimePush>(too_many_us)));
}

// 3.4.1 / 3.4.2: work mode 1 = record video; the ACK: code 0, mode 1.
TEST(PsdkBridgeGolden, CameraWorkMode) {
  EXPECT_EQ(decoded<SetCameraWorkMode>({0x01}).mode, CameraWorkMode::kRecordVideo);
  CameraWorkModeAck ack;
  ack.mode = CameraWorkMode::kRecordVideo;
  EXPECT_EQ(encoded(ack), (Bytes{0x00, 0x01}));
}

// 3.4.11: metering 1 = average (0 centre, 2 spot); 3.4.15: focus 1 = auto (0 manual).
TEST(PsdkBridgeGolden, MeteringAndFocusModes) {
  EXPECT_EQ(decoded<SetMeteringMode>({0x01}).mode, MeteringMode::kAverage);
  EXPECT_EQ(decoded<SetMeteringMode>({0x02}).mode, MeteringMode::kSpot);
  EXPECT_EQ(decoded<SetFocusMode>({0x01}).mode, FocusMode::kAuto);
  EXPECT_EQ(decoded<SetFocusMode>({0x00}).mode, FocusMode::kManual);
}

// 3.4.33 ACK: code 0, bits 0..4 (command set, optical zoom, digital zoom, focus, metering) all
// set = 0x1F. (DJI's V1.0.0 header names bits 1 and 2 the other way round; all set, it does not
// matter here.)
TEST(PsdkBridgeGolden, CameraCapabilityAck) {
  CameraCapabilityAck ack;
  ack.supported.camera_commands = ack.supported.optical_zoom = ack.supported.digital_zoom = true;
  ack.supported.focus = ack.supported.metering = true;
  EXPECT_EQ(encoded(ack), (Bytes{0x00, 0x1F}));
  ack.supported.optical_zoom = false;  // bit 1
  EXPECT_EQ(encoded(ack), (Bytes{0x00, 0x1D}));
}

// 3.5.5: floats pitch -30.0 = 0xC1F00000, roll 0, yaw 20.0 = 0x41A00000.
TEST(PsdkBridgeGolden, ControlGimbalAngle) {
  const Bytes bytes = {0x00, 0x00, 0xF0, 0xC1, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xA0, 0x41};
  const ControlGimbalAngle d = decoded<ControlGimbalAngle>(bytes);
  EXPECT_EQ(d.pitch_deg, -30.0f);
  EXPECT_EQ(d.roll_deg, 0.0f);
  EXPECT_EQ(d.yaw_deg, 20.0f);
  EXPECT_EQ(encoded(d), bytes);
}

// 3.2.4 ACK: code 0, 4 widgets. 3.4.24 ACK: code 0, float factor 2.0 = 0x40000000.
TEST(PsdkBridgeGolden, WidgetCountAndOpticalZoomFactor) {
  WidgetListLengthAck widgets;
  widgets.count = 4;
  EXPECT_EQ(encoded(widgets), (Bytes{0x00, 0x04}));
  OpticalZoomFactorAck zoom;
  zoom.factor_x = 2.0f;
  EXPECT_EQ(encoded(zoom), (Bytes{0x00, 0x00, 0x00, 0x00, 0x40}));
}

// 3.4.3: action 1 = start; 3.4.7: action 0 = stop recording.
TEST(PsdkBridgeGolden, ShootPhotoAndRecordActions) {
  EXPECT_EQ(decoded<ShootPhoto>({0x01}).action, ShootPhotoAction::kStart);
  EXPECT_EQ(decoded<ShootPhoto>({0x00}).action, ShootPhotoAction::kStop);
  EXPECT_EQ(decoded<RecordVideo>({0x00}).action, RecordAction::kStop);
}

// 3.4.4 ACK: code 0, bits 0 single + 3 storing = 0x09, uint16 countdown 0.
TEST(PsdkBridgeGolden, ShootPhotoStateAck) {
  ShootPhotoStateAck ack;
  ack.state.shooting_single = true;
  ack.state.storing = true;
  EXPECT_EQ(encoded(ack), (Bytes{0x00, 0x09, 0x00, 0x00}));
}

// 3.1.5 ACK: code 0, uint32 0xAABBCCDD = version AA.BB.CC.DD: 1.2.3.4 = 0x01020304, little-endian.
TEST(PsdkBridgeGolden, SkyportVersionAck) {
  SkyportVersionAck ack;
  ack.version = Version{1, 2, 3, 4};
  EXPECT_EQ(encoded(ack), (Bytes{0x00, 0x04, 0x03, 0x02, 0x01}));
}

// 3.5.10 ACK: code 0, 1 = gimbal command set supported.
TEST(PsdkBridgeGolden, GimbalCapabilityAck) {
  GimbalCapabilityAck ack;
  ack.supported = true;
  EXPECT_EQ(encoded(ack), (Bytes{0x00, 0x01}));
}

// 3.3.7: float altitude 100.5 m = 0x42C90000; 3.3.11: type 2 = ZENMUSE Z30.
TEST(PsdkBridgeGolden, BarometricAltitudeAndOtherPayloadPushes) {
  EXPECT_EQ(decoded<BarometricAltitudePush>({0x00, 0x00, 0xC9, 0x42}).altitude_m, 100.5);
  EXPECT_EQ(decoded<OtherPayloadTypePush>({0x02}).type, OtherPayloadType::kZenmuseZ30);
}

// P28: "following" in the state report: 1 in the document's 3.5.1, 2 in DJI's headers (one enum
// for state and set, free 0, FPV 1, yaw follow 2, as 3.5.2 numbers the set).
TEST(PsdkBridgeGolden, GimbalStateModeNumbering) {
  EXPECT_EQ(gimbal_state_mode_code(GimbalMode::kFollowing, PsdkLayout::kDocument), 1);
  EXPECT_EQ(gimbal_state_mode_code(GimbalMode::kFollowing, PsdkLayout::kDjiHeaders), 2);
  EXPECT_EQ(gimbal_state_mode_code(GimbalMode::kFpv, PsdkLayout::kDocument), 2);
  EXPECT_EQ(gimbal_state_mode_code(GimbalMode::kFpv, PsdkLayout::kDjiHeaders), 1);
}

// P29: a card inserted, formatted and full: document bits 0 + 3 + 5 = 0x0029; headers bits 0 + 5
// = 0x0021 (they have no "formatted" bit). Verified and faulty: document bits 0 + 6 + 8 = 0x0141,
// headers bits 0 + 1 + 7 = 0x0083.
TEST(PsdkBridgeGolden, SdCardStateBits) {
  SdCardState full;
  full.inserted = full.formatted = full.full = true;
  EXPECT_EQ(sd_card_state_word(full, PsdkLayout::kDocument), 0x0029);
  EXPECT_EQ(sd_card_state_word(full, PsdkLayout::kDjiHeaders), 0x0021);
  SdCardState faulty;
  faulty.inserted = faulty.verified = faulty.has_error = true;
  EXPECT_EQ(sd_card_state_word(faulty, PsdkLayout::kDocument), 0x0141);
  EXPECT_EQ(sd_card_state_word(faulty, PsdkLayout::kDjiHeaders), 0x0083);
  const SdCardState back = sd_card_state_from_word(0x0083, PsdkLayout::kDjiHeaders);
  EXPECT_TRUE(back.inserted && back.verified && back.has_error);
  EXPECT_FALSE(back.read_only || back.formatted);
  // The ACK the payload sends: the document struct carrying the headers' bits. Code 0, word
  // 0x0021, then four uint32 (zero here).
  SdCardInfoAck ack;
  ack.state = full;
  const Bytes wire = encoded(sd_card_ack_for(ack, PsdkLayout::kDjiHeaders));
  ASSERT_EQ(wire.size(), 19u);
  EXPECT_EQ(wire[1], 0x21);
  EXPECT_EQ(wire[2], 0x00);
}

// P30: 3.4.5 with a uint8 interval (document, 4 bytes) or a uint16 one (headers, 5 bytes): type 6
// (interval), burst 0, count 255, interval 30 s = 0x1E, or 300 s = 0x012C.
TEST(PsdkBridgeGolden, ShootPhotoModeByLength) {
  const Bytes narrow = {0x06, 0x00, 0xFF, 0x1E};
  const Result<ShootPhotoModeWide> n = decode_shoot_photo_mode(narrow.data(), narrow.size());
  ASSERT_TRUE(n) << n.error();
  EXPECT_EQ(n->type, ShootPhotoType::kInterval);
  EXPECT_EQ(n->interval_count, 255);
  EXPECT_EQ(n->interval_s, 30);
  const Bytes wide = {0x06, 0x00, 0xFF, 0x2C, 0x01};
  const Result<ShootPhotoModeWide> w = decode_shoot_photo_mode(wide.data(), wide.size());
  ASSERT_TRUE(w) << w.error();
  EXPECT_EQ(w->interval_s, 300);
  const Bytes short_data = {0x06, 0x00, 0xFF};
  EXPECT_FALSE(decode_shoot_photo_mode(short_data.data(), short_data.size()));
  // The get ACK in each layout: code 0, type 6, burst 0, count 255, interval 30 s.
  ShootPhotoModeWide mode = n.value();
  const Result<Data> doc = encode_shoot_photo_mode_ack(mode, PsdkLayout::kDocument);
  ASSERT_TRUE(doc) << doc.error();
  EXPECT_EQ(Bytes(doc->data(), doc->data() + doc->size), (Bytes{0x00, 0x06, 0x00, 0xFF, 0x1E}));
  const Result<Data> hdr = encode_shoot_photo_mode_ack(mode, PsdkLayout::kDjiHeaders);
  ASSERT_TRUE(hdr) << hdr.error();
  EXPECT_EQ(Bytes(hdr->data(), hdr->data() + hdr->size),
            (Bytes{0x00, 0x06, 0x00, 0xFF, 0x1E, 0x00}));
  mode.interval_s = 300;  // does not fit the document's uint8: an error, not a wrapped 44
  EXPECT_FALSE(encode_shoot_photo_mode_ack(mode, PsdkLayout::kDocument));
}

// P31: 3.3.1 of 33 bytes (no OSDK fields): baseband 1, max bandwidth 20, reserved 0, connection
// bits 0 + 3 = 0x09, MSDK up max 1000, down max 2000, network max 8000, flags 0x05, MSDK up 100,
// down 200, video 4000, data 16 (uint32 each).
TEST(PsdkBridgeGolden, LinkBandwidthWithoutOsdkFields) {
  const Bytes bytes = {0x01, 0x14, 0x00, 0x09, 0xE8, 0x03, 0x00, 0x00, 0xD0, 0x07, 0x00,
                       0x00, 0x40, 0x1F, 0x00, 0x00, 0x05, 0x64, 0x00, 0x00, 0x00, 0xC8,
                       0x00, 0x00, 0x00, 0xA0, 0x0F, 0x00, 0x00, 0x10, 0x00, 0x00, 0x00};
  ASSERT_EQ(bytes.size(), kLinkBandwidthShortSize);
  bool has_osdk = true;
  const Result<LinkBandwidthPush> p = decode_link_bandwidth(bytes.data(), bytes.size(), &has_osdk);
  ASSERT_TRUE(p) << p.error();
  EXPECT_FALSE(has_osdk);
  EXPECT_EQ(p->max_image_link_bandwidth, 20);
  EXPECT_EQ(p->msdk_uplink_max_bytes_s, 1000u);
  EXPECT_EQ(p->network_max_kbit_s, 8000u);
  EXPECT_EQ(p->network_data_kbit_s, 16u);
  EXPECT_EQ(p->osdk_uplink_max_bytes_s, 0u);
  EXPECT_FALSE(decode_link_bandwidth(bytes.data(), 32, &has_osdk));  // neither length
}

}  // namespace
}  // namespace k40t::psdk
