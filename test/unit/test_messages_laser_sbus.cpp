// Laser rangefinder (document section 3.2.5) and SBUS (section 3.2.6) messages. Golden frames:
// test/data/golden/gimbal_laser_sbus.txt, written by hand from the document.
#include <gtest/gtest.h>

#include <type_traits>

#include "golden_checks.h"
#include "k40t_driver/protocol/catalogue.h"
#include "k40t_driver/protocol/messages/laser.h"
#include "k40t_driver/protocol/messages/sbus.h"
#include "message_checks.h"
#include "message_text.h"

namespace k40t::protocol {
namespace {

using namespace testing;  // the test helpers included above

const char kGolden[] = "gimbal_laser_sbus.txt";

static_assert(std::is_same_v<LaserRangeRequest::Ack, LaserRangeAck>);
static_assert(std::is_same_v<SbusConfigRequest::Ack, SbusConfigAck>);
static_assert(acked_plainly<LaserPeriodicRangeRequest, SbusRangeRequest, SbusChannelsRequest>);

CodecOptions little_endian_acks() {
  CodecOptions o;
  o.ack_byte_order = ByteOrder::kLittle;
  return o;
}

// ---- golden: 3.2.5 laser --------------------------------------------------------------------
TEST(LaserGolden, SingleRangingRequestAndAck) {
  LaserRangeRequest request;
  request.enable = true;
  expect_encodes_to(request, golden(kGolden, "laser_range"));

  const auto ack = decode_golden<LaserRangeAck>(golden(kGolden, "laser_range_ack"));
  EXPECT_EQ(ack.code, ResponseCode::kOk);
  EXPECT_DOUBLE_EQ(ack.distance_m,
                   1234.5);  // 30 39 read high byte first (docs/protocol/decisions.md#a2)
  expect_encodes_to(ack, golden(kGolden, "laser_range_ack"));
}

TEST(LaserGolden, PeriodicRangingRequestAckAndStatusFrames) {
  LaserPeriodicRangeRequest request;
  request.enable = true;
  expect_encodes_to(request, golden(kGolden, "laser_periodic_range"));
  EXPECT_EQ(decode_golden<PlainAck>(golden(kGolden, "laser_periodic_range_ack")).code,
            ResponseCode::kOk);

  const auto status =
      decode_golden<LaserPeriodicRangeStatus>(golden(kGolden, "laser_periodic_range_status", 0));
  EXPECT_EQ(status.code, ResponseCode::kOk);
  EXPECT_DOUBLE_EQ(status.distance_m, 87.6);
  expect_encodes_to(status, golden(kGolden, "laser_periodic_range_status", 0));

  const auto no_return =
      decode_golden<LaserPeriodicRangeStatus>(golden(kGolden, "laser_periodic_range_status", 1));
  EXPECT_EQ(no_return.distance_m, 0);
}

TEST(LaserGolden, PeriodicRangeIsLowByteFirstLikeEveryStatusFrame) {
  // Section 2.1: every non-ACK payload is low byte first; 123.4 m = 1234 = 0x04D2 -> D2 04. Read
  // high byte first (the ACK's default order) these bytes would be 5376.4 m.
  const auto status =
      decode_golden<LaserPeriodicRangeStatus>(golden(kGolden, "laser_periodic_range_status", 2));
  EXPECT_DOUBLE_EQ(status.distance_m, 123.4);
  expect_encodes_to(status, golden(kGolden, "laser_periodic_range_status", 2));
}

TEST(LaserStatus, StatusFrameOrderIsItsOwnOptionAndTheAckKeepsAckByteOrder) {
  // Default: the status frame little-endian, the ACK big-endian (docs/protocol/decisions.md#a2).
  auto s = decode_bytes<LaserPeriodicRangeStatus>({0x00, 0x00, 0x6C, 0x03});
  ASSERT_TRUE(s);
  EXPECT_DOUBLE_EQ(s->distance_m, 87.6);
  auto a = decode_bytes<LaserRangeAck>({0x00, 0x00, 0x03, 0x6C});
  ASSERT_TRUE(a);
  EXPECT_DOUBLE_EQ(a->distance_m, 87.6);
  // ack_byte_order does not move the status frame...
  s = decode_bytes<LaserPeriodicRangeStatus>({0x00, 0x00, 0x6C, 0x03}, little_endian_acks());
  ASSERT_TRUE(s);
  EXPECT_DOUBLE_EQ(s->distance_m, 87.6);
  // ...laser_status_byte_order does, for a pod that builds it with its ACK routine.
  CodecOptions big_status;
  big_status.laser_status_byte_order = ByteOrder::kBig;
  s = decode_bytes<LaserPeriodicRangeStatus>({0x00, 0x00, 0x03, 0x6C}, big_status);
  ASSERT_TRUE(s);
  EXPECT_DOUBLE_EQ(s->distance_m, 87.6);
  a = decode_bytes<LaserRangeAck>({0x00, 0x00, 0x03, 0x6C}, big_status);
  ASSERT_TRUE(a);
  EXPECT_DOUBLE_EQ(a->distance_m, 87.6);
}

TEST(LaserStatus, NeedsTheDistanceButTheAckMayBeARefusal) {
  expect_decode_error<LaserPeriodicRangeStatus>({0x00, 0x00}, "too short");
  auto refusal = decode_bytes<LaserRangeAck>({0x00, 0x08});
  ASSERT_TRUE(refusal) << refusal.error();
  EXPECT_EQ(refusal->code, ResponseCode::kBusy);
  EXPECT_EQ(refusal->distance_m, 0);
  expect_decode_error<LaserRangeAck>({0x00, 0x00, 0x01}, "too short");  // half a distance
}

TEST(LaserRequests, RejectUndefinedSwitchValues) {
  expect_decode_error<LaserPeriodicRangeRequest>({0x02, 0x00}, "0 (off) or 1 (on), got 2");
  expect_decode_error<LaserRangeRequest>({0xFF, 0x00}, "got 255");
}

// ---- golden: 3.2.6 SBUS ---------------------------------------------------------------------
TEST(SbusGolden, RangeRequestIsLittleEndian) {
  SbusRangeRequest m;
  m.max_value = 1811;
  m.min_value = 172;
  expect_encodes_to(m, golden(kGolden, "sbus_range"));
  const auto d = decode_golden<SbusRangeRequest>(golden(kGolden, "sbus_range"));
  EXPECT_EQ(d.max_value, 1811);
  EXPECT_EQ(d.min_value, 172);
  EXPECT_EQ(decode_golden<PlainAck>(golden(kGolden, "sbus_range_ack")).code,
            ResponseCode::kFailure);
}

TEST(SbusGolden, ChannelsAreNumberedFromOne) {
  // yaw 1 and centre 16 are 0 and 15 on the wire.
  const auto m = message_from_text<SbusChannelsRequest>(
      "stream_channel=9 zoom_channel=10 photo_channel=11 record_channel=12 pitch_channel=2 "
      "yaw_channel=1 centre_channel=16");
  expect_encodes_to(m, golden(kGolden, "sbus_channels"));
  const auto d = decode_golden<SbusChannelsRequest>(golden(kGolden, "sbus_channels"));
  EXPECT_TRUE(fields_are(d, "yaw_channel=1 centre_channel=16 record_channel=12"));
}

TEST(SbusGolden, ConfigRequestAndAck) {
  expect_encodes_to(SbusConfigRequest{}, golden(kGolden, "sbus_config"));
  const auto ack = decode_golden<SbusConfigAck>(golden(kGolden, "sbus_config_ack"));
  EXPECT_EQ(ack.code, ResponseCode::kOk);
  EXPECT_EQ(ack.range.max_value, 2000);  // 07 D0, big-endian (docs/protocol/decisions.md#a2)
  EXPECT_EQ(ack.range.min_value, 100);
  EXPECT_TRUE(fields_are(ack.channels,
                         "stream_channel=1 zoom_channel=2 photo_channel=3 record_channel=4 "
                         "pitch_channel=5 yaw_channel=6 centre_channel=7"));
  expect_encodes_to(ack, golden(kGolden, "sbus_config_ack"));
}

TEST(SbusConfigAck, RefusalReportsNoConfiguration) {
  auto ack = decode_bytes<SbusConfigAck>({0x00, 0x01});
  ASSERT_TRUE(ack);
  EXPECT_EQ(ack->code, ResponseCode::kFailure);
  EXPECT_EQ(ack->range.max_value, 0);
  EXPECT_EQ(ack->channels.stream_channel, 0);
  expect_decode_error<SbusConfigAck>({0x00, 0x00, 0x07, 0xD0, 0x00}, "too short");
}

TEST(SbusConfigAck, LittleEndianOption) {
  auto ack = decode_bytes<SbusConfigAck>({0, 0, 0xD0, 0x07, 0x64, 0x00, 0, 1, 2, 3, 4, 5, 15, 0},
                                         little_endian_acks());
  ASSERT_TRUE(ack);
  EXPECT_EQ(ack->range.max_value, 2000);
  EXPECT_EQ(ack->range.min_value, 100);
  EXPECT_EQ(ack->channels.centre_channel, 16);
}

// ---- round trips ----------------------------------------------------------------------------
TEST(LaserSbusRoundTrip, EveryStruct) {
  LaserRangeRequest single;
  single.enable = false;
  LaserRangeAck ack;
  ack.code = ResponseCode::kTimeout;
  ack.distance_m = 6553.5;
  LaserPeriodicRangeRequest periodic;
  periodic.enable = false;
  LaserPeriodicRangeStatus status;
  status.distance_m = 0.1;

  SbusRangeRequest range;
  range.max_value = 2047;
  range.min_value = 0;
  const auto channels = message_from_text<SbusChannelsRequest>(
      "stream_channel=16 zoom_channel=15 photo_channel=14 record_channel=13 pitch_channel=12 "
      "yaw_channel=11 centre_channel=1");
  SbusConfigAck config;
  config.code = ResponseCode::kBusy;
  config.range = range;
  config.channels = channels;

  for (const CodecOptions& o : {CodecOptions{}, little_endian_acks()})
    expect_round_trips(o, single, ack, periodic, status, range, channels, SbusConfigRequest{},
                       config);
}

// ---- range errors ---------------------------------------------------------------------------
TEST(LaserRanges, Distance) {
  for (double bad : {-0.1, 6553.6}) {
    LaserRangeAck ack;
    ack.distance_m = bad;
    expect_range_error(ack, "distance_m");
    LaserPeriodicRangeStatus status;
    status.distance_m = bad;
    expect_range_error(status, "distance_m");
  }
}

TEST(SbusRanges, RangeValues) {
  const SbusRangeRequest valid;
  expect_range_error(valid, "max_value", [](auto& m) { m.max_value = 2048; });
  expect_range_error(valid, "min_value", [](auto& m) { m.min_value = 2048; });
  // The minimum must be strictly less than the maximum.
  expect_range_error(valid, "min_value", [](auto& m) { m.max_value = m.min_value = 1000; });
  expect_range_error(valid, "min_value", [](auto& m) {
    m.max_value = 1000;
    m.min_value = 1001;
  });
}

TEST(SbusRanges, EveryChannel) {
  for_each_field_set_to<SbusChannelsRequest>(
      {"0", "17"}, [](const std::string& name, const SbusChannelsRequest& channels) {
        expect_range_error(channels, name);
        SbusConfigAck ack;
        ack.channels = channels;
        expect_range_error(ack, name);
      });
  SbusConfigAck ack;
  ack.range.max_value = 5000;
  expect_range_error(ack, "max_value");
}

// ---- catalogue ------------------------------------------------------------------------------
TEST(LaserSbusCatalogue, EveryMessageIsRegistered) {
  const std::pair<MessageId, const char*> expected[] = {
      {0x000400, "laser_range"},
      {0x010400, "laser_range_ack"},
      {0x000406, "laser_periodic_range"},
      {0x010406, "laser_periodic_range_ack"},
      {0x020406, "laser_periodic_range_status"},
      {0x000500, "sbus_range"},
      {0x010500, "sbus_range_ack"},
      {0x000501, "sbus_channels"},
      {0x010501, "sbus_channels_ack"},
      {0x000502, "sbus_config"},
      {0x010502, "sbus_config_ack"},
  };
  for (const auto& [id, name] : expected) {
    const MessageInfo* info = find_message(id);
    ASSERT_NE(info, nullptr) << name;
    EXPECT_STREQ(info->name, name);
  }
  EXPECT_EQ(find_message(0x020406)->direction, Direction::kPodToHost);
}

}  // namespace
}  // namespace k40t::protocol
