// `ack_byte_order: auto` (docs/protocol/decisions.md#conventions): the link's ACK byte order as it
// changes at run time (protocol::AckOrderSetting), and the parameter's values.
#include <gtest/gtest.h>

#include <atomic>
#include <thread>
#include <vector>

#include "k40t_driver/protocol/ack_order_setting.h"
#include "k40t_driver/protocol/conventions.h"
#include "k40t_driver/protocol/messages/ack.h"

namespace k40t::protocol {
namespace {

// Section 3.3: response code 0x0001 "failure". Big-endian 00 01; little-endian 01 00, which read
// big-endian is 0x0100, no code of the list (and the other way round).
const uint8_t kFailureBig[] = {0x00, 0x01};
const uint8_t kFailureLittle[] = {0x01, 0x00};
// 0x0000 "OK" reads the same both ways: it tells nothing.
const uint8_t kOk[] = {0x00, 0x00};

CodecOptions with_order(const std::string& value) {
  CodecOptions codec;
  const Status parsed = parse_ack_byte_order(value, codec);
  EXPECT_TRUE(parsed) << parsed.message();
  return codec;
}

TEST(AckOrderSetting, AFixedOrderNeverChanges) {
  AckOrderSetting little(with_order("little"));
  EXPECT_FALSE(little.automatic());
  EXPECT_FALSE(little.observe(0x010012, kFailureBig, sizeof kFailureBig));
  EXPECT_EQ(little.order(), ByteOrder::kLittle);
  EXPECT_FALSE(little.locked());
  EXPECT_EQ(little.evidence(), "");
  AckOrderSetting big(CodecOptions{});  // the default: big
  EXPECT_FALSE(big.observe(0x010012, kFailureLittle, sizeof kFailureLittle));
  EXPECT_EQ(big.order(), ByteOrder::kBig);
}

TEST(AckOrderSetting, AutoStartsBigAndLocksOnTheFirstAckThatTells) {
  AckOrderSetting setting(with_order("auto"));
  EXPECT_TRUE(setting.automatic());
  EXPECT_EQ(setting.order(), ByteOrder::kBig);
  EXPECT_TRUE(setting.codec_with(CodecOptions{}).ack_byte_order_auto);
  EXPECT_FALSE(setting.observe(0x010012, kOk, sizeof kOk));
  EXPECT_FALSE(setting.locked());
  EXPECT_TRUE(setting.observe(0x010012, kFailureLittle, sizeof kFailureLittle));
  EXPECT_TRUE(setting.locked());
  EXPECT_EQ(setting.order(), ByteOrder::kLittle);
  EXPECT_EQ(setting.evidence(), "ACK 0x010012 bytes 1-2: 01 00");
  // Locked for the rest of the run: an ACK that reads big changes nothing.
  EXPECT_FALSE(setting.observe(0x010012, kFailureBig, sizeof kFailureBig));
  EXPECT_EQ(setting.order(), ByteOrder::kLittle);
  EXPECT_EQ(setting.evidence(), "ACK 0x010012 bytes 1-2: 01 00");
}

TEST(AckOrderSetting, DecodesFollowTheSwitch) {
  AckOrderSetting setting(with_order("auto"));
  CodecOptions configured;
  configured.ack_byte_order_auto = true;
  configured.angle_command_scale = 50;  // the rest is kept as configured
  // 01 00 read big-endian before the switch: 0x0100, no code of section 3.3.
  EXPECT_NE(ack_response_code(kFailureLittle, 2, setting.codec_with(configured)),
            ResponseCode::kFailure);
  setting.observe(0x010012, kFailureLittle, sizeof kFailureLittle);
  const CodecOptions now = setting.codec_with(configured);
  EXPECT_EQ(ack_response_code(kFailureLittle, 2, now), ResponseCode::kFailure);
  EXPECT_EQ(now.ack_byte_order, ByteOrder::kLittle);
  EXPECT_FALSE(now.ack_byte_order_auto);
  EXPECT_EQ(now.angle_command_scale, 50);
}

// Decoders on other threads while the receive thread locks: whoever sees the lock sees its order,
// and every decode reads one whole order (big before, little after), never a mix.
TEST(AckOrderSetting, ReadersOnOtherThreadsSeeOneOrderAtATime) {
  for (int round = 0; round < 50; ++round) {
    AckOrderSetting setting(with_order("auto"));
    std::atomic<bool> go{false};
    std::atomic<int> wrong{0};
    std::vector<std::thread> readers;
    for (int i = 0; i < 3; ++i) {
      readers.emplace_back([&] {
        while (!go.load()) std::this_thread::yield();
        for (int n = 0; n < 2000; ++n) {
          const bool locked = setting.locked();
          const CodecOptions c = setting.codec_with(CodecOptions{});
          if (locked && c.ack_byte_order != ByteOrder::kLittle) ++wrong;
          if (c.ack_byte_order_auto == (c.ack_byte_order == ByteOrder::kLittle)) ++wrong;
        }
      });
    }
    go = true;
    setting.observe(0x010012, kFailureLittle, sizeof kFailureLittle);
    for (std::thread& t : readers) t.join();
    EXPECT_EQ(wrong.load(), 0) << "round " << round;
    EXPECT_EQ(setting.order(), ByteOrder::kLittle);
  }
}

TEST(AckOrderSetting, TheParameterTakesAutoAndSaysSo) {
  CodecOptions codec;
  CrcCoverage crc = CrcCoverage::kAuto;
  ASSERT_TRUE(set_convention(ConventionRefs{crc, codec}, "ack_byte_order", "auto"));
  EXPECT_TRUE(codec.ack_byte_order_auto);
  EXPECT_EQ(codec.ack_byte_order, ByteOrder::kBig);
  const ConventionInfo* info = find_convention("ack_byte_order");
  ASSERT_NE(info, nullptr);
  EXPECT_EQ(info->get(*info, ConstConventionRefs{crc, codec}), "auto");
  ASSERT_TRUE(set_convention(ConventionRefs{crc, codec}, "ack_byte_order", "little"));
  EXPECT_FALSE(codec.ack_byte_order_auto);
  EXPECT_EQ(info->get(*info, ConstConventionRefs{crc, codec}), "little");
  const Status bad = set_convention(ConventionRefs{crc, codec}, "ack_byte_order", "middle");
  ASSERT_FALSE(bad);
  EXPECT_EQ(bad.message(), "ack_byte_order must be big, little or auto, got 'middle'");
  EXPECT_EQ(codec.ack_byte_order, ByteOrder::kLittle);  // a bad value loses nothing
  EXPECT_FALSE(parse_ack_byte_order("Auto", codec));
}

}  // namespace
}  // namespace k40t::protocol
