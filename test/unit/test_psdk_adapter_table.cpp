// skyport_sim's own ACK table and request writer (psdk/sim/adapter_table.h): it reads ACK bytes
// written by hand from the document, refuses what it must, and agrees with the payload's codec on
// every ACK's size (two readings of the document written apart: a disagreement means one is wrong).
#include <gtest/gtest.h>

#include <vector>

#include "k40t_driver/psdk/catalogue.h"
#include "k40t_driver/psdk/sim/adapter_table.h"

namespace k40t::psdk::sim::table {
namespace {

Data data_of(const std::vector<uint8_t>& bytes) {
  Data d;
  std::copy(bytes.begin(), bytes.end(), d.bytes.begin());
  d.size = bytes.size();
  return d;
}

// 3.4.21: code 0, uint16 max 517, min 47, step 1, in 0.1 mm.
TEST(AdapterTable, ReadsOpticalZoomSpecInMillimetres) {
  const Result<Reading> r = read({0x04, 0x36}, data_of({0x00, 0x05, 0x02, 0x2F, 0x00, 0x01, 0x00}));
  ASSERT_TRUE(r) << r.error();
  EXPECT_NEAR(r->number("max_mm"), 51.7, 1e-9);
  EXPECT_NEAR(r->number("min_mm"), 4.7, 1e-9);
  EXPECT_NEAR(r->number("step_mm"), 0.1, 1e-9);
}

// 3.4.4: code 0, bits 1 interval + 3 storing = 0x0A, uint16 countdown 5.
TEST(AdapterTable, ReadsPhotoStateBits) {
  const Result<Reading> r = read({0x04, 0x04}, data_of({0x00, 0x0A, 0x05, 0x00}));
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->number("single"), 0);
  EXPECT_EQ(r->number("interval"), 1);
  EXPECT_EQ(r->number("burst"), 0);
  EXPECT_EQ(r->number("storing"), 1);
  EXPECT_EQ(r->number("countdown_s"), 5);
}

// 3.1.4: product name in bytes 2:33, NUL-terminated; 3.5.9: floats in 0.1 deg/s (-100.0 =
// 0xC2C80000 is -10 deg/s).
TEST(AdapterTable, ReadsTextsAndScaledFloats) {
  std::vector<uint8_t> info(113, 0x00);
  info[1] = 'K';
  info[2] = '4';
  const Result<Reading> r = read({0x01, 0x04}, data_of(info));
  ASSERT_TRUE(r) << r.error();
  EXPECT_EQ(r->text("product_name"), "K4");
  const Result<Reading> g =
      read({0x05, 0x09},
           data_of({0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0x00, 0xC8, 0xC2}));
  ASSERT_TRUE(g) << g.error();
  EXPECT_NEAR(g->number("yaw_deg_s"), -10.0, 1e-6);
}

TEST(AdapterTable, RefusesARefusalAShortAckAndAnUnknownCommand) {
  const Result<Reading> refused = read({0x04, 0x02}, data_of({0x02}));
  ASSERT_FALSE(refused);
  EXPECT_NE(refused.error().find("get_camera_work_mode"), std::string::npos) << refused.error();
  EXPECT_FALSE(read({0x04, 0x08}, data_of({0x00, 0x01, 0x4B})));  // 3 of 4 bytes
  EXPECT_FALSE(read({0x04, 0x50}, data_of({0x00})));
}

// 3.5.4: int16 rates then the action; 3.5.5: three floats (-30.0 = 0xC1F00000).
TEST(AdapterTable, WritesRequestsLittleEndian) {
  EXPECT_EQ(Request().i16(-100).i16(0).i16(100).u8(1).bytes(),
            (std::vector<uint8_t>{0x9C, 0xFF, 0x00, 0x00, 0x64, 0x00, 0x01}));
  EXPECT_EQ(Request().f32(-30.0f).bytes(), (std::vector<uint8_t>{0x00, 0x00, 0xF0, 0xC1}));
}

TEST(AdapterTable, AgreesWithThePayloadsCodecOnEverySize) {
  for (const AckEntry& entry : acks()) {
    const CommandInfo* info = find_command({entry.set, entry.id}, PacketType::kAck);
    ASSERT_NE(info, nullptr) << entry.name;
    EXPECT_EQ(entry.size, info->min_size) << entry.name << " (" << entry.section << ")";
  }
}

}  // namespace
}  // namespace k40t::psdk::sim::table
