// Validation of PSDK command structs: out-of-range values are refused before any byte is
// written, with a message that names the struct, the field and the allowed range; short DATA is
// refused on decoding with the struct's name.
#include <gtest/gtest.h>

#include <cmath>

#include "k40t_driver/psdk/commands/all.h"
#include "request_with.h"

namespace k40t::psdk {
namespace {

using testing::request_with;

template <class T>
std::string encode_error(const T& m) {
  const Result<Data> d = encode_data(m);
  EXPECT_FALSE(d) << T::kName << " should have been refused";
  return d ? std::string() : d.error();
}

#define EXPECT_MENTIONS(text, part) EXPECT_NE((text).find(part), std::string::npos) << (text)

TEST(PsdkValidation, BatteryPercentage) {
  BatteryInfoPush m;
  m.percentage = 101;
  const std::string e = encode_error(m);
  EXPECT_MENTIONS(e, "battery_info_push");
  EXPECT_MENTIONS(e, "'percentage' must be 0..100");
  EXPECT_MENTIONS(e, "got 101");
}

TEST(PsdkValidation, GimbalSpeedLimits) {
  ControlGimbalSpeed m;
  m.yaw_rate_deg_s = 180.0;
  EXPECT_TRUE(encode_data(m));
  m.yaw_rate_deg_s = -180.1;
  EXPECT_MENTIONS(encode_error(m), "'yaw_rate_deg_s' must be -180..180 deg/s");
  m.yaw_rate_deg_s = std::nan("");
  EXPECT_MENTIONS(encode_error(m), "yaw_rate_deg_s");
}

TEST(PsdkValidation, ScaledIntegerCapacity) {
  GpsPush m;
  m.relative_height_m = 3276.8;  // int16 x 0.1 m holds up to 3276.7
  EXPECT_MENTIONS(encode_error(m), "'relative_height_m' must be -3276.8..3276.7");
  m.relative_height_m = 0;
  m.latitude_rad = 1.6;  // > pi/2
  EXPECT_MENTIONS(encode_error(m), "'latitude_rad'");
}

TEST(PsdkValidation, EnumCodesTheDocumentDefines) {
  SetShootPhotoMode m;
  m.type = static_cast<ShootPhotoType>(2);
  const std::string e = encode_error(m);
  EXPECT_MENTIONS(e, "'type' has no code 2");
  EXPECT_MENTIONS(e, "1 (single), 4 (burst), 6 (interval)");
  EXPECT_MENTIONS(
      encode_error(request_with(&StartContinuousZoom::speed, static_cast<ZoomSpeed>(79))),
      "'speed' has no code 79");
}

TEST(PsdkValidation, IntervalShootingNeedsCountAndInterval) {
  SetShootPhotoMode m;
  m.type = ShootPhotoType::kInterval;
  m.interval_count = 0;
  m.interval_s = 5;
  EXPECT_MENTIONS(encode_error(m), "'interval_count' must be 1..255");
  m.interval_count = kIntervalShootUntilStopped;
  EXPECT_TRUE(encode_data(m));
  m.type = ShootPhotoType::kSingle;  // counts are ignored for single shots
  m.interval_count = 0;
  m.interval_s = 0;
  EXPECT_TRUE(encode_data(m));
}

TEST(PsdkValidation, BitFieldRanges) {
  SetSpotMeteringZone m;
  m.zone = {12, 0};
  EXPECT_MENTIONS(encode_error(m), "'column' must be 0..11");
  m.zone = {0, 8};
  EXPECT_MENTIONS(encode_error(m), "'row' must be 0..7");
  GetPosition p;
  p.points[0].event.event_index = 8192;
  EXPECT_MENTIONS(encode_error(p), "'event_index' must be 0..8191");
  p.points[0].event.event_index = 0;
  p.points[0].event.target_point_index = 8;
  EXPECT_MENTIONS(encode_error(p), "'target_point_index' must be 0..7");
}

TEST(PsdkValidation, FocusZoneAndZoomFactors) {
  EXPECT_MENTIONS(encode_error(request_with<SetFocusZone>(&SetFocusZone::x, 1.5f)),
                  "'x' must be 0..1");
  EXPECT_MENTIONS(
      encode_error(request_with<SetDigitalZoomFactor>(&SetDigitalZoomFactor::factor_x, 0.5f)),
      "'factor_x' must be 1..");
  EXPECT_MENTIONS(
      encode_error(request_with<OpticalZoomFactorAck>(&OpticalZoomFactorAck::factor_x, 31.0f)),
      "'factor_x' must be 1..30");
}

TEST(PsdkValidation, TextMustLeaveRoomForItsTerminator) {
  ProductInfoAck m;
  m.product_name = std::string(31, 'n');
  EXPECT_TRUE(encode_data(m));
  m.product_name = std::string(32, 'n');
  EXPECT_MENTIONS(encode_error(m), "'product_name' must be at most 31 bytes");
  m.product_name = std::string("a\0b", 3);
  EXPECT_MENTIONS(encode_error(m), "NUL");
  FloatingWindowMessage w;
  w.text = std::string(127, 'w');
  EXPECT_TRUE(encode_data(w));
  w.text += 'w';
  EXPECT_MENTIONS(encode_error(w), "'text' must be at most 127 bytes");
}

TEST(PsdkValidation, OpaqueDataLengths) {
  Handshake h;
  EXPECT_MENTIONS(encode_error(h), "'data' must be 1..32 bytes, got 0");
  TransparentToMobile t;
  t.data = Blob<128>::from(std::string(128, 'x'));
  EXPECT_TRUE(encode_data(t));
  Handshake long_handshake;
  long_handshake.data = Blob<32>::from(std::string(33, 'h'));
  EXPECT_MENTIONS(encode_error(long_handshake), "'data' must be 1..32 bytes, got 33");
  TransparentFromOnboard o;
  o.data.size = 0;
  EXPECT_MENTIONS(encode_error(o), "1..255 bytes");
}

TEST(PsdkValidation, WidgetLists) {
  WidgetListDataAck m;
  m.type = WidgetType::kChooseList;
  m.name = "Palette";
  m.choose_item_count = 0;
  EXPECT_MENTIONS(encode_error(m), "'choose_item_count' must be 1..10");
  m.choose_item_count = 1;
  m.choose_items[0] = std::string(16, 'i');
  EXPECT_MENTIONS(encode_error(m), "'choose_items' must be at most 15 bytes");
  m.type = WidgetType::kButton;
  m.choose_items[0].clear();
  EXPECT_MENTIONS(encode_error(m), "unless the widget is a choose list");
  EXPECT_MENTIONS(encode_error(request_with(&WidgetGroupDataAck::count, 16)),
                  "'count' must be 1..15");
  EXPECT_MENTIONS(encode_error(request_with(&GetWidgetGroupData::group, 2)),
                  "'group' must be 0..1");
}

TEST(PsdkValidation, PositionCountsAndOffsets) {
  GetPosition p;
  p.count = 0;
  EXPECT_MENTIONS(encode_error(p), "'count' must be 1..5");
  p.count = 6;
  EXPECT_MENTIONS(encode_error(p), "'count' must be 1..5");
  p.count = 1;
  p.points[0].time_offset_us = 2000001;
  EXPECT_MENTIONS(encode_error(p), "'time_offset_us' must be 0..2000000");
  GetPositionAck a;
  a.count = 5;  // the document allows 5, DATA cannot hold them
  const std::string e = encode_error(a);
  EXPECT_MENTIONS(e, "290 bytes");
  EXPECT_MENTIONS(e, "256");
}

TEST(PsdkValidation, DateFields) {
  AppDateTimePush m;
  m.time.month = 13;
  EXPECT_MENTIONS(encode_error(m), "'month' must be 1..12");
  EXPECT_MENTIONS(encode_error(request_with(&UtcTimePush::microsecond, 1000000)),
                  "'microsecond' must be 0..999999 us");
}

TEST(PsdkDecoding, ShortDataNamesTheStruct) {
  const uint8_t two[] = {0x00, 0x00};
  const Result<GpsPush> gps = decode_data<GpsPush>(two, 2);
  ASSERT_FALSE(gps);
  EXPECT_MENTIONS(gps.error(), "gps_push: DATA of 2 bytes is too short, need 20");
  const Result<GimbalStateAck> ack = decode_data<GimbalStateAck>(two, 2);
  ASSERT_FALSE(ack);
  EXPECT_MENTIONS(ack.error(), "need 9");
  const Result<BatteryInfoAck> empty = decode_data<BatteryInfoAck>(two, 0);
  ASSERT_FALSE(empty);
  EXPECT_MENTIONS(empty.error(), "need 1");
}

TEST(PsdkDecoding, RefusalMayBeTheCodeAlone) {
  const uint8_t unsupported[] = {0x02};
  const Result<GimbalStateAck> ack = decode_data<GimbalStateAck>(unsupported, 1);
  ASSERT_TRUE(ack) << ack.error();
  EXPECT_EQ(ack->code, AckCode::kUnsupported);
  const uint8_t ok_without_body[] = {0x00};
  EXPECT_FALSE(decode_data<GimbalStateAck>(ok_without_body, 1));
}

TEST(PsdkDecoding, CountsBeyondCapacityAreErrorsNotOverflows) {
  const uint8_t group[] = {0x00, 0x10};  // 16 widgets
  const Result<WidgetGroupDataAck> g = decode_data<WidgetGroupDataAck>(group, sizeof(group));
  ASSERT_FALSE(g);
  EXPECT_MENTIONS(g.error(), "at most 15");
  const uint8_t position[] = {0x06, 0x00, 0xe8, 0x07, 0x01, 0x01, 0x00, 0x00, 0x00};
  const Result<GetPosition> p = decode_data<GetPosition>(position, sizeof(position));
  ASSERT_FALSE(p);
  const uint8_t list[35 + 1] = {0x00, 0x04};  // choose list claiming 0 items is fine...
  EXPECT_TRUE(decode_data<WidgetListDataAck>(list, sizeof(list)));
  uint8_t too_many[36] = {0x00, 0x04};
  too_many[35] = 11;  // ...11 are not
  const Result<WidgetListDataAck> l = decode_data<WidgetListDataAck>(too_many, sizeof(too_many));
  ASSERT_FALSE(l);
  EXPECT_MENTIONS(l.error(), "at most 10");
}

TEST(PsdkDecoding, TruncatedVariableDataIsAnError) {
  const uint8_t group[] = {0x00, 0x02, 0x02, 0x00, 0x01, 0x00, 0x00, 0x00, 0x03};  // 2nd widget cut
  const Result<WidgetGroupDataAck> g = decode_data<WidgetGroupDataAck>(group, sizeof(group));
  ASSERT_FALSE(g);
  EXPECT_MENTIONS(g.error(), "get_widget_group_data_ack");
}

}  // namespace
}  // namespace k40t::psdk
