// ack_byte_order from traffic (docs/protocol/decisions.md#a2, #conventions): which byte orders an
// ACK's bytes fit, and the driver's `conventions` diagnostic confirming or contradicting the value
// in force against a simulated pod that sends little-endian ACKs.
#include <gtest/gtest.h>

#include <vector>

#include "conventions_rig.h"
#include "k40t_driver/protocol/ack_byte_order_evidence.h"
#include "k40t_driver/protocol/messages/thermal.h"

namespace k40t::driver::testing {
namespace {

namespace p = protocol;

// Section 3.3: 0x0001 is "failure"; read the other way it is 0x0100, no code of the list.
TEST(AckByteOrderEvidence, AResponseCodeTellsUnlessItIsZero) {
  const uint8_t failure_big[] = {0x00, 0x01};
  p::AckOrderFit fit;
  p::fit_ack_byte_order(0x010012, failure_big, sizeof failure_big, fit);
  EXPECT_TRUE(fit.big);
  EXPECT_FALSE(fit.little);
  EXPECT_EQ(fit.evidence, "ACK 0x010012 bytes 1-2: 00 01");
  const uint8_t ok[] = {0x00, 0x00};
  p::AckOrderFit nothing;
  p::fit_ack_byte_order(0x010012, ok, sizeof ok, nothing);
  EXPECT_FALSE(nothing.tells());
}

// Section 3.2.2.1, ACK 0x010100: code (bytes 1-2), then bytes 11-12 the high-temperature alarm
// threshold, int16 in 0.1 degC, -1000..5000 or -2732. 50.0 degC = 500 = 0x01F4: big-endian 01 F4
// (as little-endian 0xF401 = -3071, out of range); little-endian F4 01 the other way round. The
// other ranged fields read the same both ways here.
TEST(AckByteOrderEvidence, TheThermalReadBacksThresholdTells) {
  std::vector<uint8_t> ack(22, 0);
  ack[14] = ack[15] = 0x01;  // bytes 15-16, the difference, 1..6000: 0x0101 reads 257 both ways
  ack[10] = 0x01;
  ack[11] = 0xF4;
  p::AckOrderFit big;
  p::fit_ack_byte_order(0x010100, ack.data(), ack.size(), big);
  EXPECT_TRUE(big.big);
  EXPECT_FALSE(big.little);
  EXPECT_EQ(big.evidence, "ACK 0x010100 bytes 11-12: 01 F4");
  ack[10] = 0xF4;
  ack[11] = 0x01;
  p::AckOrderFit little;
  p::fit_ack_byte_order(0x010100, ack.data(), ack.size(), little);
  EXPECT_FALSE(little.big);
  EXPECT_TRUE(little.little);
  // A refusal (code only) says nothing of the fields.
  p::AckOrderFit refusal;
  p::fit_ack_byte_order(0x010100, ack.data(), 2, refusal);
  EXPECT_FALSE(refusal.tells());
}

void read_thermal_settings(ConventionsRig& rig) {
  // Read back: only the response code (0x0000) decodes the same both ways; the fields may not.
  rig.driver().request_typed(p::ThermalReadSettingsRequest{});
}

TEST(AckByteOrderEvidence, ADriverReadingBigAgainstALittleEndianPodIsNamed) {
  ConventionsRig rig({}, {},
                     [](sim::SimOptions& o) { o.codec.ack_byte_order = p::ByteOrder::kLittle; });
  read_thermal_settings(rig);
  ASSERT_TRUE(rig.contradicts("ack_byte_order"));
  const std::string why = rig.reading("ack_byte_order").contradiction;
  EXPECT_NE(why.find("ACK 0x010100 bytes"), std::string::npos) << why;
  EXPECT_NE(why.find("set ack_byte_order: little"), std::string::npos) << why;
}

TEST(AckByteOrderEvidence, TheRightValueIsConfirmedInTheDiagnostic) {
  ConventionsRig rig({}, {"ack_byte_order=little"},
                     [](sim::SimOptions& o) { o.codec.ack_byte_order = p::ByteOrder::kLittle; });
  read_thermal_settings(rig);
  EXPECT_TRUE(test::eventually([&] {
    return rig.reading("ack_byte_order").source.find("parameter, confirmed by ACK 0x010100") !=
           std::string::npos;
  })) << rig.reading("ack_byte_order").source;
  EXPECT_EQ(rig.reading("ack_byte_order").contradiction, "");
}

}  // namespace
}  // namespace k40t::driver::testing
